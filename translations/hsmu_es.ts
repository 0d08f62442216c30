<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>CompareCommand</name>
    <message>
        <source>Run the paper&apos;s comparison protocol (reference, initial, updated).</source>
        <translation>Ejecuta el protocolo de comparación del artículo (referencia, inicial, actualizado).</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>El subcomando.</translation>
    </message>
    <message>
        <source>Configuration file or preset name.</source>
        <translation>Archivo de configuración o nombre de preajuste.</translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation>Directorio de salida.</translation>
    </message>
    <message>
        <source>Write PNG plots.</source>
        <translation>Escribe gráficas PNG.</translation>
    </message>
    <message>
        <source>Compared numerical element (default: the first updating target).</source>
        <translation>Elemento numérico comparado (por defecto: el primer objetivo de la actualización).</translation>
    </message>
    <message>
        <source>Compared DOF (default: the element&apos;s DOF).</source>
        <translation>GDL comparado (por defecto: el GDL del elemento).</translation>
    </message>
    <message>
        <source>expected exactly one CONFIG (a file or a preset name)</source>
        <translation>se esperaba exactamente un CONFIG (un archivo o un nombre de preajuste)</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>falta --out DIR</translation>
    </message>
    <message>
        <source>%1 run %2/3: %3 %  (%4 s)</source>
        <translation>ensayo %1 %2/3: %3 %  (%4 s)</translation>
    </message>
    <message>
        <source>%1: the configuration has no online model updating (an enabled &quot;updating&quot; section); compare needs one to run the updated test</source>
        <translation>%1: la configuración no tiene actualización del modelo en línea (una sección &quot;updating&quot; habilitada); compare la necesita para ejecutar el ensayo actualizado</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1: no se puede crear el directorio de salida</translation>
    </message>
    <message>
        <source>hsmu compare: three runs (reference, initial, updated) of %1</source>
        <translation>hsmu compare: tres ensayos (referencia, inicial, actualizado) de %1</translation>
    </message>
    <message>
        <source>%1: %2 steps, %3</source>
        <translation>%1: %2 pasos, %3</translation>
    </message>
    <message>
        <source>hsmu compare: the %1 run stopped at step %2 (state %3)%4</source>
        <translation>hsmu compare: el ensayo %1 se detuvo en el paso %2 (estado %3)%4</translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation>%1: no se pudo escribir la gráfica</translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation>  salidas: %1</translation>
    </message>
</context>
<context>
    <name>ComparisonPlotExporter</name>
    <message>
        <source>reference</source>
        <translation>referencia</translation>
    </message>
    <message>
        <source>initial (not updated)</source>
        <translation>inicial (sin actualizar)</translation>
    </message>
    <message>
        <source>updated</source>
        <translation>actualizado</translation>
    </message>
    <message>
        <source>Hysteresis of %1: reference, initial and updated</source>
        <translation>Histéresis de %1: referencia, inicial y actualizado</translation>
    </message>
    <message>
        <source>Moment history of %1</source>
        <translation>Historia de momento de %1</translation>
    </message>
    <message>
        <source>Force history of %1</source>
        <translation>Historia de fuerza de %1</translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation>Momento [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation>Fuerza [%1]</translation>
    </message>
    <message>
        <source>Displacement of %1</source>
        <translation>Desplazamiento de %1</translation>
    </message>
    <message>
        <source>Displacement [m]</source>
        <translation>Desplazamiento [m]</translation>
    </message>
</context>
<context>
    <name>ComparisonTable</name>
    <message>
        <source>Comparison against the reference run: %1 force [%2], %3 displacement [m]</source>
        <translation>Comparación con el ensayo de referencia: fuerza de %1 [%2], desplazamiento de %3 [m]</translation>
    </message>
    <message>
        <source>run</source>
        <translation>ensayo</translation>
    </message>
    <message>
        <source>force NRMSE</source>
        <translation>NRMSE de fuerza</translation>
    </message>
    <message>
        <source>force peak error [%1]</source>
        <translation>error de pico de fuerza [%1]</translation>
    </message>
    <message>
        <source>displ. NRMSE</source>
        <translation>NRMSE de despl.</translation>
    </message>
    <message>
        <source>displ. peak error [m]</source>
        <translation>error de pico de despl. [m]</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <source>initial</source>
        <translation>inicial</translation>
    </message>
    <message>
        <source>updated</source>
        <translation>actualizado</translation>
    </message>
    <message>
        <source>  initial / updated NRMSE: force %1x, displacement %2x</source>
        <translation>  NRMSE inicial / actualizado: fuerza %1x, desplazamiento %2x</translation>
    </message>
    <message>
        <source>Final parameters of the updated run (%1 updates applied):</source>
        <translation>Parámetros finales del ensayo actualizado (%1 actualizaciones aplicadas):</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>parámetro</translation>
    </message>
    <message>
        <source>value</source>
        <translation>valor</translation>
    </message>
    <message>
        <source>std</source>
        <translation>desv. est.</translation>
    </message>
    <message>
        <source>true</source>
        <translation>verdadero</translation>
    </message>
</context>
<context>
    <name>ConsoleCommand</name>
    <message>
        <source>HSMU Console: hybrid simulation with online model updating.
Subcommands: run CONFIG --out DIR ..., compare CONFIG --out DIR ..., material --law ... (see hsmu run --help, hsmu compare --help, docs/cli.md).</source>
        <translation>HSMU Console: simulación híbrida con actualización del modelo en línea.
Subcomandos: run CONFIG --out DIR ..., compare CONFIG --out DIR ..., material --law ... (véase hsmu run --help, hsmu compare --help, docs/cli.md).</translation>
    </message>
    <message>
        <source>Load a preset or configuration and start it.</source>
        <translation>Carga un preajuste o una configuración y lo inicia.</translation>
    </message>
    <message>
        <source>Ground-motion record file.</source>
        <translation>Archivo del registro de movimiento del suelo.</translation>
    </message>
    <message>
        <source>Test time per wall time (0: as fast as possible).</source>
        <translation>Tiempo de ensayo por tiempo real transcurrido (0: lo más rápido posible).</translation>
    </message>
    <message>
        <source>Grab the window into this PNG file, then quit.</source>
        <translation>Captura la ventana en este archivo PNG y luego sale.</translation>
    </message>
    <message>
        <source>Seconds before the screenshot (default 4).</source>
        <translation>Segundos antes de la captura (por defecto 4).</translation>
    </message>
    <message>
        <source>unknown subcommand &apos;%1&apos; (expected run, compare or material)</source>
        <translation>subcomando desconocido &apos;%1&apos; (se esperaba run, compare o material)</translation>
    </message>
    <message>
        <source>--screenshot-after: expected a number of seconds</source>
        <translation>--screenshot-after: se esperaba un número de segundos</translation>
    </message>
    <message>
        <source>--speed: expected a number</source>
        <translation>--speed: se esperaba un número</translation>
    </message>
    <message>
        <source>Actuator controller: builtin (the default) or tcp://HOST:PORT.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--controller: %1</source>
        <translation type="unfinished">--controller: %1</translation>
    </message>
</context>
<context>
    <name>ExportCommand</name>
    <message>
        <source>Write a run record (HDF5) as CSV files, one per group.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation type="unfinished">El subcomando.</translation>
    </message>
    <message>
        <source>The record (record.h5).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output directory for the CSVs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected exactly one FILE.h5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing --csv DIR</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation type="unfinished">%1: no se puede crear el directorio de salida</translation>
    </message>
    <message>
        <source>%1 steps, %2 alarms; written:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MaterialCommand</name>
    <message>
        <source>Drive one hysteresis law with a deformation history.</source>
        <translation>Somete una ley de histéresis a una historia de deformación.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>El subcomando.</translation>
    </message>
    <message>
        <source>Law: %1.</source>
        <translation>Ley: %1.</translation>
    </message>
    <message>
        <source>A law parameter (repeatable).</source>
        <translation>Un parámetro de la ley (repetible).</translation>
    </message>
    <message>
        <source>Deformation history (CSV or text).</source>
        <translation>Historia de deformación (CSV o texto).</translation>
    </message>
    <message>
        <source>Output CSV (default: stdout).</source>
        <translation>CSV de salida (por defecto: stdout).</translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>argumento inesperado &apos;%1&apos;</translation>
    </message>
    <message>
        <source>missing --law (one of %1)</source>
        <translation>falta --law (una de %1)</translation>
    </message>
    <message>
        <source>missing --history FILE</source>
        <translation>falta --history FILE</translation>
    </message>
    <message>
        <source>--param &apos;%1&apos;: expected NAME=VALUE with a finite number</source>
        <translation>--param &apos;%1&apos;: se esperaba NAME=VALUE con un número finito</translation>
    </message>
</context>
<context>
    <name>OverrideOptions</name>
    <message>
        <source>Ground-motion record file.</source>
        <translation>Archivo del registro de movimiento del suelo.</translation>
    </message>
    <message>
        <source>Ground-motion scale factor.</source>
        <translation>Factor de escala del movimiento del suelo.</translation>
    </message>
    <message>
        <source>Integration step [s].</source>
        <translation>Paso de integración [s].</translation>
    </message>
    <message>
        <source>Test duration [s].</source>
        <translation>Duración del ensayo [s].</translation>
    </message>
    <message>
        <source>--%1: expected a %2 number, found &apos;%3&apos;</source>
        <translation>--%1: se esperaba un número %2, se encontró &apos;%3&apos;</translation>
    </message>
    <message>
        <source>positive</source>
        <translation>positivo</translation>
    </message>
</context>
<context>
    <name>PlotExporter</name>
    <message>
        <source>%1: unknown plot format &apos;%2&apos; (expected png, svg or pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation type="unfinished">%1: no se pudo escribir la gráfica</translation>
    </message>
</context>
<context>
    <name>PreflightDialog</name>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ReplayCommand</name>
    <message>
        <source>Re-identify a recorded specimen, or imported measured data, offline.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation type="unfinished">El subcomando.</translation>
    </message>
    <message>
        <source>A run record (record.h5).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re-run the identification headless.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured data: CSV of time, deformation, force with units.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Units of the imported columns time,deformation,force, e.g. s,mm,kN.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ukf or nelder-mead.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>JSON with &quot;model&quot; and/or &quot;updating&quot; settings to override.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The recorded specimen to identify.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation type="unfinished">Directorio de salida.</translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation type="unfinished">argumento inesperado &apos;%1&apos;</translation>
    </message>
    <message>
        <source>give either FILE.h5 or --import DATA.csv, not both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected FILE.h5 (a run record) or --import DATA.csv</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--units applies to --import only (a record has its units)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation type="unfinished">falta --out DIR</translation>
    </message>
    <message>
        <source>%1 identification of %2: %3 samples, dt %4 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>parameter</source>
        <translation type="unfinished">parámetro</translation>
    </message>
    <message>
        <source>initial</source>
        <translation type="unfinished">inicial</translation>
    </message>
    <message>
        <source>final</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>std</source>
        <translation type="unfinished">desv. est.</translation>
    </message>
    <message>
        <source>online</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  final model over the whole history: RMS force error %1 %2 (%3 % of RMS force); inspector fit error at the end %4 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  Nelder-Mead fits accepted: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  estimator warnings: %1 (see summary.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation type="unfinished">  salidas: %1</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation type="unfinished">%1: no se puede crear el directorio de salida</translation>
    </message>
</context>
<context>
    <name>ReplayWindowCommand</name>
    <message>
        <source>Replay a recorded test (an HDF5 run record) in a window.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation type="unfinished">El subcomando.</translation>
    </message>
    <message>
        <source>The run record (record.h5).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test seconds per wall second (default 1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start playing at once.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grab the window into this PNG file, then quit.</source>
        <translation type="unfinished">Captura la ventana en este archivo PNG y luego sale.</translation>
    </message>
    <message>
        <source>Seconds before the screenshot (default 3).</source>
        <translation type="unfinished">Segundos antes de la captura (por defecto 4). {3)?}</translation>
    </message>
    <message>
        <source>expected one record file: hsmu replay FILE.h5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--speed: expected a positive number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--screenshot-after: expected a number of seconds</source>
        <translation type="unfinished">--screenshot-after: se esperaba un número de segundos</translation>
    </message>
</context>
<context>
    <name>RunCommand</name>
    <message>
        <source>%1 %  t = %2 s  %3 steps/s</source>
        <translation>%1 %  t = %2 s  %3 pasos/s</translation>
    </message>
    <message>
        <source>hsmu run: link fault at t = %1 s (step %2): %3; reconnecting (attempt %4 of %5)</source>
        <translation>hsmu run: fallo del enlace en t = %1 s (paso %2): %3; reconectando (intento %4 de %5)</translation>
    </message>
    <message>
        <source>hsmu run: --approval ignored: the configuration has no updating</source>
        <translation>hsmu run: se ignora --approval: la configuración no tiene actualización del modelo</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1: no se puede crear el directorio de salida</translation>
    </message>
    <message>
        <source>the test cannot start: %1</source>
        <translation>el ensayo no puede iniciarse: %1</translation>
    </message>
    <message>
        <source>hsmu run: test held at t = %1 s (step %2): %3</source>
        <translation>hsmu run: ensayo retenido en t = %1 s (paso %2): %3</translation>
    </message>
    <message>
        <source>hsmu run: the test stopped unexpectedly (state %1)</source>
        <translation>hsmu run: el ensayo se detuvo inesperadamente (estado %1)</translation>
    </message>
    <message>
        <source>%1: the record could not be written: %2</source>
        <translation>%1: no se pudo escribir el registro: %2</translation>
    </message>
    <message>
        <source>%1: write failed</source>
        <translation>%1: error de escritura</translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation>%1: no se pudo escribir la gráfica</translation>
    </message>
    <message>
        <source>hsmu run: connecting to %1 (%2 protocol)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RunOptions</name>
    <message>
        <source>Run a hybrid test headless.</source>
        <translation>Ejecuta un ensayo híbrido sin interfaz gráfica.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>El subcomando.</translation>
    </message>
    <message>
        <source>Configuration file or preset name.</source>
        <translation>Archivo de configuración o nombre de preajuste.</translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation>Directorio de salida.</translation>
    </message>
    <message>
        <source>Run an explicit scheme past its stability limit.</source>
        <translation>Ejecuta un esquema explícito más allá de su límite de estabilidad.</translation>
    </message>
    <message>
        <source>Write PNG plots.</source>
        <translation>Escribe gráficas PNG.</translation>
    </message>
    <message>
        <source>Shared secret for the controller.</source>
        <translation>Secreto compartido con el controlador.</translation>
    </message>
    <message>
        <source>After a lost link or a timeout, resume (and reconnect) up to N times before giving up (default 0: hold and exit 2).</source>
        <translation>Tras una pérdida del enlace o un tiempo de espera agotado, reanuda (y reconecta) hasta N veces antes de desistir (por defecto 0: retener y salir con código 2).</translation>
    </message>
    <message>
        <source>Decision on update proposals of the onApproval policy: manual, approveAll or rejectAll (default: the configuration&apos;s).</source>
        <translation>Decisión sobre las propuestas de actualización de la política onApproval: manual, approveAll o rejectAll (por defecto: la de la configuración).</translation>
    </message>
    <message>
        <source>expected exactly one CONFIG (a file or a preset name)</source>
        <translation>se esperaba exactamente un CONFIG (un archivo o un nombre de preajuste)</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>falta --out DIR</translation>
    </message>
    <message>
        <source>--controller: %1</source>
        <translation>--controller: %1</translation>
    </message>
    <message>
        <source>--reconnect: expected a whole number &gt;= 0, found &apos;%1&apos;</source>
        <translation>--reconnect: se esperaba un número entero &gt;= 0, se encontró &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--approval: expected manual, approveAll or rejectAll, found &apos;%1&apos;</source>
        <translation>--approval: se esperaba manual, approveAll o rejectAll, se encontró &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Actuator controller: builtin (in-process virtual specimens, the default), tcp://HOST:PORT (hsmu-controller or a lab controller, in the configuration&apos;s controller.protocol, native by default), simapp://HOST:PORT (an OpenFresco SimApp server) or generictcp://HOST:PORT (a server for OpenFresco&apos;s GenericTCP).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RunReport</name>
    <message>
        <source>  identified parameters of %1 (%2, final value ± std):</source>
        <translation>  parámetros identificados de %1 (%2, valor final ± desv. est.):</translation>
    </message>
    <message>
        <source>  updates applied: %1, proposals pending: %2, final fit error: %3</source>
        <translation>  actualizaciones aplicadas: %1, propuestas pendientes: %2, error de ajuste final: %3</translation>
    </message>
    <message>
        <source>Test: %1</source>
        <translation>Ensayo: %1</translation>
    </message>
    <message>
        <source>  state: %1, steps: %2 of %3, test time: %4 s, wall time: %5 s</source>
        <translation>  estado: %1, pasos: %2 de %3, tiempo de ensayo: %4 s, tiempo real: %5 s</translation>
    </message>
    <message>
        <source>  peak displacement:</source>
        <translation>  desplazamiento máximo:</translation>
    </message>
    <message>
        <source>  peak force:</source>
        <translation>  fuerza máxima:</translation>
    </message>
    <message>
        <source>  alarms: none</source>
        <translation>  alarmas: ninguna</translation>
    </message>
    <message>
        <source>  alarms:</source>
        <translation>  alarmas:</translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation>  salidas: %1</translation>
    </message>
</context>
<context>
    <name>RunState</name>
    <message>
        <source>no test loaded</source>
        <translation>ningún ensayo cargado</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>listo</translation>
    </message>
    <message>
        <source>running</source>
        <translation>en ejecución</translation>
    </message>
    <message>
        <source>paused</source>
        <translation>en pausa</translation>
    </message>
    <message>
        <source>holding</source>
        <translation>en retención</translation>
    </message>
    <message>
        <source>finished</source>
        <translation>terminado</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>detenido</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fallido</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::AlarmList</name>
    <message>
        <source>limit exceeded</source>
        <translation>límite superado</translation>
    </message>
    <message>
        <source>control fault</source>
        <translation>fallo de control</translation>
    </message>
    <message>
        <source>element fault</source>
        <translation>fallo de elemento</translation>
    </message>
    <message>
        <source>integrator fault</source>
        <translation>fallo del integrador</translation>
    </message>
    <message>
        <source>operator</source>
        <translation>operador</translation>
    </message>
    <message>
        <source>stability</source>
        <translation>estabilidad</translation>
    </message>
    <message>
        <source>model fit error</source>
        <translation>error de ajuste del modelo</translation>
    </message>
    <message>
        <source>fracture</source>
        <translation>fractura</translation>
    </message>
    <message>
        <source>estimator rejected</source>
        <translation>rechazo del estimador</translation>
    </message>
    <message>
        <source>parameter at a bound</source>
        <translation>parámetro en un límite</translation>
    </message>
    <message>
        <source>actuator tracking</source>
        <translation>seguimiento del actuador</translation>
    </message>
    <message>
        <source>model update</source>
        <translation>actualización del modelo</translation>
    </message>
    <message>
        <source>info</source>
        <translation>información</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>advertencia</translation>
    </message>
    <message>
        <source>critical</source>
        <translation>crítico</translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation type="unfinished">Tiempo [s]</translation>
    </message>
    <message>
        <source>Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Severity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>console</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes, %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ControlBar</name>
    <message>
        <source>Test control</source>
        <translation>Control del ensayo</translation>
    </message>
    <message>
        <source>Preset: </source>
        <translation>Preajuste: </translation>
    </message>
    <message>
        <source>Test configurations shipped with the console</source>
        <translation>Configuraciones de ensayo incluidas con la consola</translation>
    </message>
    <message>
        <source>(choose a preset)</source>
        <translation>(elija un preajuste)</translation>
    </message>
    <message>
        <source>Open configuration...</source>
        <translation>Abrir configuración...</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Iniciar</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausar</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Reanudar</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <source> Speed: </source>
        <translation> Velocidad: </translation>
    </message>
    <message>
        <source>Test time per wall-clock time</source>
        <translation>Tiempo de ensayo por tiempo real</translation>
    </message>
    <message>
        <source>0.5 x real time</source>
        <translation>0,5 x tiempo real</translation>
    </message>
    <message>
        <source>real time</source>
        <translation>tiempo real</translation>
    </message>
    <message>
        <source>2 x real time</source>
        <translation>2 x tiempo real</translation>
    </message>
    <message>
        <source>5 x real time</source>
        <translation>5 x tiempo real</translation>
    </message>
    <message>
        <source>as fast as possible</source>
        <translation>lo más rápido posible</translation>
    </message>
    <message>
        <source>Single step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run exactly one integration step, then stay paused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Emergency hold (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold the test at once, between two steps (%1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::HistoryPlot</name>
    <message>
        <source>Time [s]</source>
        <translation>Tiempo [s]</translation>
    </message>
    <message>
        <source>Displacement history</source>
        <translation>Historia de desplazamiento</translation>
    </message>
    <message>
        <source>Displacement [m]</source>
        <translation>Desplazamiento [m]</translation>
    </message>
    <message>
        <source>Ground motion</source>
        <translation>Movimiento del suelo</translation>
    </message>
    <message>
        <source>Ground acceleration [m/s²]</source>
        <translation>Aceleración del suelo [m/s²]</translation>
    </message>
    <message>
        <source>Ground acceleration</source>
        <translation>Aceleración del suelo</translation>
    </message>
    <message>
        <source>Force history</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force</source>
        <translation type="unfinished">Fuerza</translation>
    </message>
    <message>
        <source>Moment history</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation type="unfinished">Momento [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation type="unfinished">Fuerza [%1]</translation>
    </message>
    <message>
        <source>Tracking of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotation [%1]</source>
        <translation type="unfinished">Rotación [%1]</translation>
    </message>
    <message>
        <source>Deformation [%1]</source>
        <translation type="unfinished">Deformación [%1]</translation>
    </message>
    <message>
        <source>commanded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inspector fit error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit error [-]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fit error</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::HysteresisPlot</name>
    <message>
        <source>Deformation</source>
        <translation>Deformación</translation>
    </message>
    <message>
        <source>Force</source>
        <translation>Fuerza</translation>
    </message>
    <message>
        <source>%1 (specimen, measured)</source>
        <translation>%1 (probeta, medido)</translation>
    </message>
    <message>
        <source>%1 (numerical)</source>
        <translation>%1 (numérico)</translation>
    </message>
    <message>
        <source>Hysteresis of %1</source>
        <translation>Histéresis de %1</translation>
    </message>
    <message>
        <source>Hysteresis: specimen and numerical twins</source>
        <translation>Histéresis: probeta y gemelos numéricos</translation>
    </message>
    <message>
        <source>Rotation [%1]</source>
        <translation>Rotación [%1]</translation>
    </message>
    <message>
        <source>Deformation [%1]</source>
        <translation>Deformación [%1]</translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation>Momento [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation>Fuerza [%1]</translation>
    </message>
    <message>
        <source>auxiliary model (%1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::LivePlotsPanel</name>
    <message>
        <source>PNG image (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SVG drawing (*.svg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export this plot...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export all plots...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export all plots to</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::MainWindow</name>
    <message>
        <source>HSMU Console</source>
        <translation>HSMU Console</translation>
    </message>
    <message>
        <source>Alarms and events</source>
        <translation>Alarmas y eventos</translation>
    </message>
    <message>
        <source>cannot load %1: %2</source>
        <translation>no se puede cargar %1: %2</translation>
    </message>
    <message>
        <source>Open configuration</source>
        <translation>Abrir configuración</translation>
    </message>
    <message>
        <source>Test configurations (*.json);;All files (*)</source>
        <translation>Configuraciones de ensayo (*.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Configuration error</source>
        <translation>Error de configuración</translation>
    </message>
    <message>
        <source>loaded %1 (%2)</source>
        <translation>cargado %1 (%2)</translation>
    </message>
    <message>
        <source>HSMU Console - %1</source>
        <translation>HSMU Console - %1</translation>
    </message>
    <message>
        <source>the test cannot start: %1</source>
        <translation>el ensayo no puede iniciarse: %1</translation>
    </message>
    <message>
        <source>Acknowledge all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test setup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pending updates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledge selected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Critical alarms stay red until acknowledged (double-click or the buttons).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open configuration...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open r&amp;ecord...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Settings...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>update #%1 approved by the operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>update #%1 rejected by the operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>setup not applied: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>preparing the test (pre-flight)...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>start cancelled at the pre-flight check</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pre-flight confirmed by the operator (zero offsets)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>built-in virtual lab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (connects at start)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n critical alarm(s) not acknowledged. Latest: %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ParameterPlot</name>
    <message>
        <source>Time [s]</source>
        <translation>Tiempo [s]</translation>
    </message>
    <message>
        <source>± %1σ</source>
        <translation>± %1σ</translation>
    </message>
    <message>
        <source>estimate</source>
        <translation>estimación</translation>
    </message>
    <message>
        <source>true value</source>
        <translation>valor verdadero</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ParameterTableModel</name>
    <message>
        <source>Double-click to edit; effective on the next step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sigma</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lower</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ParametersPanel</name>
    <message>
        <source>No online model updating in this test.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normalized RMS fit error above which the inspector requests an update; effective on the next step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit-error threshold [-]:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value, sigma (1 standard deviation) and bounds in the law&apos;s normalized units (u / u_ref, F / F_ref). Double-click a bound to edit it; bound and lock edits take effect on the next step.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 on %2 at step %3: fit error e = %4 (threshold %5), %6 updates applied</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PendingUpdatesPanel</name>
    <message>
        <source>every step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at zero-force crossings of the target</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every N steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on the operator&apos;s approval</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>N = </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Proposed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change [%]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current and proposed values in the law&apos;s normalized units</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply updates:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No online model updating in this test.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Updates are applied %1; choose &quot;on the operator&apos;s approval&quot; to decide each one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n update(s) waiting for a decision.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>#%1 %2 at t = %3 s (step %4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Approve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reject</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PreflightDialog</name>
    <message>
        <source>Pre-flight check</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Integration and stability</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time step dt [s]:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steps:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground motion:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, PGA %2 m/s²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>omega_max [rad/s]:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>omega_max dt [-] / limit:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unconditionally stable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stable: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>UNSTABLE: %1%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (forced by the configuration)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Specimens: limits and initial measured values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max |d|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max |F|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max |Δd| per step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured d</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured F</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured d and F: what the specimen reported after the link was prepared, before any target was sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>I confirm the zero offsets: with the specimen unloaded the actuator displacement and the load cell read zero.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start test</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReplayWindow</name>
    <message>
        <source>Open record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HSMU records (*.h5 *.hdf5);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open the record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HSMU Replay - %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Speed </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test seconds per wall second</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scrub through the record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished">Pausar</translation>
    </message>
    <message>
        <source> t = %1 s   step %2 of %3 </source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SettingsDialog</name>
    <message>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear recent files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>empty: tests are not recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Record folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Record folder (HDF5):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Language:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A new language applies the next time the console starts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recent files:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SetupPanel</name>
    <message>
        <source>No configuration loaded: choose a preset or open a file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safety limits (0 = none; the specimen&apos;s units)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Specimen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max |d|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max |F|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max |Δd| per step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply (reload the test)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the configuration&apos;s record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground motion file:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scale [-]:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time step dt [s]:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>whole record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duration [s]:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>explicit Newmark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>alpha-OS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>alpha-OS alpha [-]:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>built-in virtual lab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hsmu-controller over TCP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Specimens driven by:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Host:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Port:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Online model updating</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply updates:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>N [steps]:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit-error threshold [-]:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground motion record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground motions (*.AT2 *.at2 *.txt *.csv *.dat);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Configuration: %1
%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(built in)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>built-in %1 record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>d in %1, F in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no configuration loaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>safety limit of %1: &apos;%2&apos; is not a number &gt;= 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this configuration has no updating section to enable</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TestStatusBar</name>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>step %1 / %2</source>
        <translation>paso %1 / %2</translation>
    </message>
    <message>
        <source>%1 steps/s</source>
        <translation>%1 pasos/s</translation>
    </message>
    <message>
        <source>no link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>link: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>recording: %1/%2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TestWorker</name>
    <message>
        <source>stopped by the operator</source>
        <translation>detenido por el operador</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>retención de emergencia por el operador</translation>
    </message>
    <message>
        <source>the record cannot be written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this test has no model updating</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the lower bound must be a number not above the upper bound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: bounds [%2, %3] refused (they would not keep the law admissible)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the %2 cannot lock this parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>update #%1 was not applied (no longer pending, or refused by the law; see the alarms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>update #%1 is no longer pending</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the fit-error threshold must be a positive number</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
