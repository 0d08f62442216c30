<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>ActuatorLimitText</name>
    <message>
        <source>%1, actuator &apos;%2&apos; (%3)</source>
        <translation>%1, actuador &apos;%2&apos; (%3)</translation>
    </message>
    <message>
        <source>force control</source>
        <translation>control de fuerza</translation>
    </message>
    <message>
        <source>displacement control</source>
        <translation>control de desplazamiento</translation>
    </message>
    <message>
        <source>stroke |s|</source>
        <translation>carrera |s|</translation>
    </message>
    <message>
        <source>force |F|</source>
        <translation>fuerza |F|</translation>
    </message>
    <message>
        <source>stroke increment |Δs| per step</source>
        <translation>incremento de carrera |Δs| por paso</translation>
    </message>
    <message>
        <source>PASS  %1: %2 up to %3 %4 (t = %5 s), within the limit %6 %4</source>
        <translation>CORRECTO  %1: %2 hasta %3 %4 (t = %5 s), dentro del límite %6 %4</translation>
    </message>
    <message>
        <source>FAIL  %1: %2 reaches %3 %4 (t = %5 s), past the limit %6 %4: the test will hold at that step</source>
        <translation>FALLA  %1: %2 llega a %3 %4 (t = %5 s), más allá del límite %6 %4: el ensayo se detendrá en ese paso</translation>
    </message>
    <message>
        <source>%1: %2 limit %3 %4, checked at every step (it depends on the specimen&apos;s response)</source>
        <translation>%1: límite de %2 %3 %4, comprobado en cada paso (depende de la respuesta de la probeta)</translation>
    </message>
    <message>
        <source>%1: no %2 limit</source>
        <translation>%1: sin límite de %2</translation>
    </message>
</context>
<context>
    <name>AlarmText</name>
    <message>
        <source>test resumed after an automatic reconnect</source>
        <translation>ensayo reanudado tras una reconexión automática</translation>
    </message>
    <message>
        <source>operator hold</source>
        <translation>detención por el operador</translation>
    </message>
    <message>
        <source>predicted displacement is not finite</source>
        <translation>el desplazamiento predicho no es finito</translation>
    </message>
    <message>
        <source>restoring force or response is not finite</source>
        <translation>la fuerza restauradora o la respuesta no es finita</translation>
    </message>
    <message>
        <source>test held: %1</source>
        <translation>ensayo detenido: %1</translation>
    </message>
    <message>
        <source>test resumed</source>
        <translation>ensayo reanudado</translation>
    </message>
    <message>
        <source>model error %1 % above the threshold %2 %</source>
        <translation>error del modelo %1 % por encima del umbral %2 %</translation>
    </message>
    <message>
        <source>sudden strength loss: measured force %1 short of the model&apos;s by %2</source>
        <translation>pérdida súbita de resistencia: la fuerza medida %1 queda %2 por debajo de la del modelo</translation>
    </message>
    <message>
        <source>identification step rejected: %1</source>
        <translation>paso de identificación rechazado: %1</translation>
    </message>
    <message>
        <source>actuator tracking error J2 = %1 % (delay J1 = %2 s)</source>
        <translation>error de seguimiento del actuador J2 = %1 % (retardo J1 = %2 s)</translation>
    </message>
    <message>
        <source>%1 has been at its bound %2 for %3 s</source>
        <translation>%1 lleva %3 s en su límite %2</translation>
    </message>
    <message>
        <source>update not applied: the approval queue is full (%1 proposals pending); this and later offers are in the record until the operator decides</source>
        <translation>actualización no aplicada: la cola de aprobación está llena (%1 propuestas pendientes); esta y las siguientes ofertas quedan en el registro hasta que el operador decida</translation>
    </message>
    <message>
        <source>offsets proposed for the twins: u0 = %1, F0 = %2 (they apply only when the operator approves them)</source>
        <translation>desplazamientos de cero propuestos para los gemelos: u0 = %1, F0 = %2 (solo se aplican si el operador los aprueba)</translation>
    </message>
    <message>
        <source>%1: omega_max dt = %2 (omega_max = %3 rad/s, dt = %4 s) within the limit %5</source>
        <translation>%1: omega_max dt = %2 (omega_max = %3 rad/s, dt = %4 s) dentro del límite %5</translation>
    </message>
    <message>
        <source>%1 is unstable for this model: omega_max dt = %2 exceeds %3 (omega_max = %4 rad/s, dt = %5 s); use dt &lt;= %6 s or the alphaOS integrator</source>
        <translation>%1 es inestable para este modelo: omega_max dt = %2 supera %3 (omega_max = %4 rad/s, dt = %5 s); use dt &lt;= %6 s o el integrador alphaOS</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>operator</source>
        <translation>operador</translation>
    </message>
    <message>
        <source>operator at the console</source>
        <translation>operador en la consola</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>retención de emergencia por el operador</translation>
    </message>
    <message>
        <source>emergency hold: %1 (%2)</source>
        <translation>retención de emergencia: %1 (%2)</translation>
    </message>
    <message>
        <source>emergency hold: %1</source>
        <translation>retención de emergencia: %1</translation>
    </message>
    <message>
        <source>target deformation is not a finite number</source>
        <translation>la deformación objetivo no es un número finito</translation>
    </message>
    <message>
        <source>target deformation |d| = %1 exceeds the limit %2</source>
        <translation>la deformación objetivo |d| = %1 supera el límite %2</translation>
    </message>
    <message>
        <source>target increment |d - d_last| = %1 exceeds the limit %2</source>
        <translation>el incremento objetivo |d - d_anterior| = %1 supera el límite %2</translation>
    </message>
    <message>
        <source>measured force is not a finite number</source>
        <translation>la fuerza medida no es un número finito</translation>
    </message>
    <message>
        <source>measured force |F| = %1 exceeds the limit %2</source>
        <translation>la fuerza medida |F| = %1 supera el límite %2</translation>
    </message>
    <message>
        <source>measured deformation is not a finite number</source>
        <translation>la deformación medida no es un número finito</translation>
    </message>
    <message>
        <source>measured deformation |d| = %1 exceeds the limit %2 (+%3 % tolerance)</source>
        <translation>la deformación medida |d| = %1 supera el límite %2 (tolerancia +%3 %)</translation>
    </message>
    <message>
        <source>%1 (forced by the operator)</source>
        <translation>%1 (forzado por el operador)</translation>
    </message>
    <message>
        <source>updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), limit %4; K0 and damping kept from the start: the explicit integration of the updated model may diverge</source>
        <translation>modelo actualizado: omega_max dt = %1 (omega_max = %2 rad/s, %3 al inicio), límite %4; K0 y amortiguamiento se mantienen del inicio: la integración explícita del modelo actualizado puede divergir</translation>
    </message>
    <message>
        <source>updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), limit %4; K0 and damping kept from the start</source>
        <translation>modelo actualizado: omega_max dt = %1 (omega_max = %2 rad/s, %3 al inicio), límite %4; K0 y amortiguamiento se mantienen del inicio</translation>
    </message>
    <message>
        <source>auxiliary model did not converge at deformation %1</source>
        <translation>el modelo auxiliar no convergió en la deformación %1</translation>
    </message>
    <message>
        <source>stopped by the operator</source>
        <translation>detenido por el operador</translation>
    </message>
    <message>
        <source>synthetic Kanai-Tajimi (seed %1)</source>
        <translation>sintético Kanai-Tajimi (semilla %1)</translation>
    </message>
    <message>
        <source>link to %1 is down (%2); resume to reconnect</source>
        <translation>el enlace con %1 está caído (%2); reanude para reconectar</translation>
    </message>
    <message>
        <source>link to %1: %2</source>
        <translation>enlace con %1: %2</translation>
    </message>
    <message>
        <source>controller at %1: %2</source>
        <translation>controlador en %1: %2</translation>
    </message>
    <message>
        <source>TCP link is holding: %1</source>
        <translation>el enlace TCP está detenido: %1</translation>
    </message>
    <message>
        <source>no connection to %1 within %2 s</source>
        <translation>sin conexión con %1 en %2 s</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>no se puede conectar con %1: %2</translation>
    </message>
    <message>
        <source>cannot resolve %1: %2</source>
        <translation>no se puede resolver %1: %2</translation>
    </message>
    <message>
        <source>the controller closed the connection</source>
        <translation>el controlador cerró la conexión</translation>
    </message>
    <message>
        <source>the peer closed the connection</source>
        <translation>el otro extremo cerró la conexión</translation>
    </message>
    <message>
        <source>connection lost while sending: %1</source>
        <translation>conexión perdida al enviar: %1</translation>
    </message>
    <message>
        <source>connection lost: %1</source>
        <translation>conexión perdida: %1</translation>
    </message>
    <message>
        <source>malformed frame from the controller: %1</source>
        <translation>trama mal formada del controlador: %1</translation>
    </message>
    <message>
        <source>the controller was silent for %1 s</source>
        <translation>el controlador no respondió durante %1 s</translation>
    </message>
    <message>
        <source>not connected: %1</source>
        <translation>sin conexión: %1</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>sin conexión</translation>
    </message>
    <message>
        <source>no reply within %1 s</source>
        <translation>sin respuesta en %1 s</translation>
    </message>
    <message>
        <source>closed by the console</source>
        <translation>cerrado por la consola</translation>
    </message>
    <message>
        <source>closed by an emergency hold</source>
        <translation>cerrado por una retención de emergencia</translation>
    </message>
    <message>
        <source>no answer to the hello</source>
        <translation>sin respuesta al saludo (hello)</translation>
    </message>
    <message>
        <source>no measurement for step %1</source>
        <translation>sin medición del paso %1</translation>
    </message>
    <message>
        <source>the controller&apos;s specimen is at step %1 but the test committed %2 (was it restarted without its --state file?); cannot resume without a jump</source>
        <translation>la probeta del controlador está en el paso %1 pero el ensayo confirmó %2 (¿se reinició sin su archivo --state?); no se puede reanudar sin un salto</translation>
    </message>
    <message>
        <source>specimen &apos;%1&apos; holds: %2</source>
        <translation>la probeta &apos;%1&apos; está detenida: %2</translation>
    </message>
    <message>
        <source>interlock: %1</source>
        <translation>enclavamiento: %1</translation>
    </message>
    <message>
        <source>specimen fault: %1</source>
        <translation>fallo de la probeta: %1</translation>
    </message>
    <message>
        <source>controller fault: %1</source>
        <translation>fallo del controlador: %1</translation>
    </message>
    <message>
        <source>actuator position |d| = %1 exceeds the limit %2</source>
        <translation>la posición del actuador |d| = %1 supera el límite %2</translation>
    </message>
    <message>
        <source>console hold</source>
        <translation>detención desde la consola</translation>
    </message>
    <message>
        <source>wrong token</source>
        <translation>token incorrecto</translation>
    </message>
    <message>
        <source>another console session is running a test on this controller (one session at a time)</source>
        <translation>otra sesión de consola está ejecutando un ensayo en este controlador (una sesión a la vez)</translation>
    </message>
    <message>
        <source>this controller has no specimen named &apos;%1&apos;</source>
        <translation>este controlador no tiene ninguna probeta llamada &apos;%1&apos;</translation>
    </message>
    <message>
        <source>held from the previous console session: %1</source>
        <translation>detenido desde la sesión de consola anterior: %1</translation>
    </message>
    <message>
        <source>virtual specimen (%1 law, force noise std %2, %3 actuator, fracture event)</source>
        <translation>probeta virtual (ley %1, ruido de fuerza σ %2, actuador %3, evento de fractura)</translation>
    </message>
    <message>
        <source>virtual specimen (%1 law, force noise std %2, %3 actuator)</source>
        <translation>probeta virtual (ley %1, ruido de fuerza σ %2, actuador %3)</translation>
    </message>
    <message>
        <source>specimen &apos;%1&apos; on hsmu-controller (%2 law, force noise std %3, %4 actuator, %5 pace, %6 Hz predictor-corrector, fracture event), %7 committed steps</source>
        <translation>probeta &apos;%1&apos; en hsmu-controller (ley %2, ruido de fuerza σ %3, actuador %4, ritmo %5, predictor-corrector a %6 Hz, evento de fractura), %7 pasos confirmados</translation>
    </message>
    <message>
        <source>specimen &apos;%1&apos; on hsmu-controller (%2 law, force noise std %3, %4 actuator, %5 pace, %6 Hz predictor-corrector), %7 committed steps</source>
        <translation>probeta &apos;%1&apos; en hsmu-controller (ley %2, ruido de fuerza σ %3, actuador %4, ritmo %5, predictor-corrector a %6 Hz), %7 pasos confirmados</translation>
    </message>
    <message>
        <source>TCP link %1 to %2</source>
        <translation>enlace TCP %1 con %2</translation>
    </message>
    <message>
        <source>specimen &apos;%1&apos;</source>
        <translation>probeta &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1 link %2 for specimen &apos;%3&apos; (%4)</source>
        <translation>enlace %1 %2 para la probeta &apos;%3&apos; (%4)</translation>
    </message>
    <message>
        <source>prediction rejected: %1</source>
        <translation>predicción rechazada: %1</translation>
    </message>
    <message>
        <source>update rejected: %1</source>
        <translation>actualización rechazada: %1</translation>
    </message>
    <message>
        <source>Bouc-Wen integration failed (%1): %2</source>
        <translation>falló la integración de Bouc-Wen (%1): %2</translation>
    </message>
    <message>
        <source>%1; z and e could not be advanced either: step skipped</source>
        <translation>%1; tampoco se pudieron avanzar z y e: paso omitido</translation>
    </message>
    <message>
        <source>the state is not finite</source>
        <translation>el estado no es finito</translation>
    </message>
    <message>
        <source>the measurement is not finite</source>
        <translation>la medición no es finita</translation>
    </message>
    <message>
        <source>the predicted measurement is not finite</source>
        <translation>la medición predicha no es finita</translation>
    </message>
    <message>
        <source>the innovation covariance is not positive definite (check R)</source>
        <translation>la covarianza de la innovación no es definida positiva (revise R)</translation>
    </message>
    <message>
        <source>the filter has not been initialized</source>
        <translation>el filtro no se ha inicializado</translation>
    </message>
    <message>
        <source>Nelder-Mead fit failed: %1</source>
        <translation>falló el ajuste de Nelder-Mead: %1</translation>
    </message>
    <message>
        <source>Nelder-Mead trigger %1 kept the parameters (RMS %2 not improved, %3 evaluations, %4 ms)</source>
        <translation>el disparo %1 de Nelder-Mead conservó los parámetros (RMS %2 sin mejora, %3 evaluaciones, %4 ms)</translation>
    </message>
    <message>
        <source>Nelder-Mead trigger %1: RMS force error %2 -&gt; %3 (%4 evaluations, %5 ms)</source>
        <translation>disparo %1 de Nelder-Mead: error RMS de fuerza %2 -&gt; %3 (%4 evaluaciones, %5 ms)</translation>
    </message>
    <message>
        <source>the measured deformation or force is not finite: step skipped</source>
        <translation>la deformación o la fuerza medidas no son finitas: paso omitido</translation>
    </message>
    <message>
        <source>%1 line %2: %3</source>
        <translation>%1, línea %2: %3</translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos;: the file does not exist</source>
        <translation>no se puede abrir &apos;%1&apos;: el archivo no existe</translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos;: it is a folder, not a file</source>
        <translation>no se puede abrir &apos;%1&apos;: es una carpeta, no un archivo</translation>
    </message>
    <message>
        <source>cannot read &apos;%1&apos;: not a regular file (a device, pipe or socket)</source>
        <translation>no se puede leer &apos;%1&apos;: no es un archivo normal (un dispositivo, tubería o socket)</translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos; for reading (permissions?)</source>
        <translation>no se puede abrir &apos;%1&apos; para lectura (¿permisos?)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a text file (binary data at byte %2)</source>
        <translation>&apos;%1&apos; no es un archivo de texto (datos binarios en el byte %2)</translation>
    </message>
    <message>
        <source>the file is empty (expected a PEER AT2 record)</source>
        <translation>el archivo está vacío (se esperaba un registro PEER AT2)</translation>
    </message>
    <message>
        <source>the file is empty (no acceleration values)</source>
        <translation>el archivo está vacío (sin valores de aceleración)</translation>
    </message>
    <message>
        <source>no data lines (only comments or blank lines)</source>
        <translation>no hay líneas de datos (solo comentarios o líneas en blanco)</translation>
    </message>
    <message>
        <source>the file is empty: expected an AT2 header (&apos;NPTS=..., DT=...&apos; on line 4), two columns (time, acceleration) or one column of values</source>
        <translation>el archivo está vacío: se esperaba una cabecera AT2 (&apos;NPTS=..., DT=...&apos; en la línea 4), dos columnas (tiempo, aceleración) o una columna de valores</translation>
    </message>
    <message>
        <source>no data lines: expected an AT2 header (&apos;NPTS=..., DT=...&apos; on line 4), two columns (time, acceleration) or one column of values</source>
        <translation>no hay líneas de datos: se esperaba una cabecera AT2 (&apos;NPTS=..., DT=...&apos; en la línea 4), dos columnas (tiempo, aceleración) o una columna de valores</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>se esperaba un número, se encontró %1</translation>
    </message>
    <message>
        <source>non-finite value %1</source>
        <translation>valor no finito %1</translation>
    </message>
    <message>
        <source>the time step dt must be &gt; 0 s, got %1</source>
        <translation>el paso de tiempo dt debe ser &gt; 0 s, se recibió %1</translation>
    </message>
    <message>
        <source>expected two columns (time, acceleration), found %1 value(s)</source>
        <translation>se esperaban dos columnas (tiempo, aceleración), se encontraron %1 valor(es)</translation>
    </message>
    <message>
        <source>only one sample: the time step cannot be determined</source>
        <translation>solo una muestra: no se puede determinar el paso de tiempo</translation>
    </message>
    <message>
        <source>time must increase: %1 s follows %2 s</source>
        <translation>el tiempo debe crecer: %1 s sigue a %2 s</translation>
    </message>
    <message>
        <source>non-uniform time step: %1 s follows %2 s (step %3 s, mean step %4 s); a uniform step is required (tolerance 1e-6 relative)</source>
        <translation>paso de tiempo no uniforme: %1 s sigue a %2 s (paso %3 s, paso medio %4 s); se requiere un paso uniforme (tolerancia relativa 1e-6)</translation>
    </message>
    <message>
        <source>a single column of acceleration values needs the time step dt, and none was given</source>
        <translation>una sola columna de valores de aceleración necesita el paso de tiempo dt, y no se indicó ninguno</translation>
    </message>
    <message>
        <source>cannot open the configuration file</source>
        <translation>no se puede abrir el archivo de configuración</translation>
    </message>
    <message>
        <source>not a regular file (a folder, device, pipe or socket)</source>
        <translation>no es un archivo normal (una carpeta, dispositivo, tubería o socket)</translation>
    </message>
    <message>
        <source>not valid JSON (%1)</source>
        <translation>JSON no válido (%1)</translation>
    </message>
    <message>
        <source>cannot be opened (no such file)</source>
        <translation>no se puede abrir (no existe el archivo)</translation>
    </message>
    <message>
        <source>not an HSMU record (not an HDF5 file)</source>
        <translation>no es un registro HSMU (no es un archivo HDF5)</translation>
    </message>
    <message>
        <source>not an HSMU record (no schema_version attribute)</source>
        <translation>no es un registro HSMU (sin atributo schema_version)</translation>
    </message>
    <message>
        <source>damaged record (%1)</source>
        <translation>registro dañado (%1)</translation>
    </message>
    <message>
        <source>ideal</source>
        <translation>ideal</translation>
    </message>
    <message>
        <source>lag</source>
        <translation>con retardo de primer orden</translation>
    </message>
    <message>
        <source>delay</source>
        <translation>con retardo puro</translation>
    </message>
    <message>
        <source>fast</source>
        <translation>rápido</translation>
    </message>
    <message>
        <source>real-time</source>
        <translation>tiempo real</translation>
    </message>
    <message>
        <source>the record holds no step</source>
        <translation>el registro no contiene ningún paso</translation>
    </message>
    <message>
        <source>RTHS run held: %1</source>
        <translation>ensayo RTHS detenido: %1</translation>
    </message>
    <message>
        <source>live delay J1 = %1 ms over the warning threshold %2 ms</source>
        <translation>retardo en vivo J1 = %1 ms por encima del umbral de aviso %2 ms</translation>
    </message>
    <message>
        <source>live delay J1 = %1 ms over the critical threshold %2 ms</source>
        <translation>retardo en vivo J1 = %1 ms por encima del umbral crítico %2 ms</translation>
    </message>
    <message>
        <source>live tracking error J2 = %1 % over the warning threshold %2 %</source>
        <translation>error de seguimiento en vivo J2 = %1 % por encima del umbral de aviso %2 %</translation>
    </message>
    <message>
        <source>live tracking error J2 = %1 % over the critical threshold %2 %</source>
        <translation>error de seguimiento en vivo J2 = %1 % por encima del umbral crítico %2 %</translation>
    </message>
    <message>
        <source>RTHS run not followed: %1</source>
        <translation>ensayo RTHS sin seguimiento: %1</translation>
    </message>
</context>
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
    <message>
        <source>--plots: this program cannot draw (run it through hsmu)</source>
        <translation>--plots: este programa no puede dibujar (ejecútelo a través de hsmu)</translation>
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
    <message>
        <source>reference</source>
        <translation>referencia</translation>
    </message>
    <message>
        <source>element</source>
        <translation>elemento</translation>
    </message>
    <message>
        <source>basic DOF</source>
        <translation>GDL básico</translation>
    </message>
    <message>
        <source>deformation NRMSE</source>
        <translation>NRMSE de deformación</translation>
    </message>
    <message>
        <source>deformation peak error</source>
        <translation>error de pico de deformación</translation>
    </message>
    <message>
        <source>force peak error</source>
        <translation>error de pico de fuerza</translation>
    </message>
    <message>
        <source>Per basic DOF against the reference run:</source>
        <translation>Por GDL básico, frente al ensayo de referencia:</translation>
    </message>
    <message>
        <source>actuator</source>
        <translation>actuador</translation>
    </message>
    <message>
        <source>control</source>
        <translation>control</translation>
    </message>
    <message>
        <source>force</source>
        <translation>fuerza</translation>
    </message>
    <message>
        <source>displacement</source>
        <translation>desplazamiento</translation>
    </message>
    <message>
        <source>Per actuator: tracking against its command, force against the reference run:</source>
        <translation>Por actuador: seguimiento de su consigna, fuerza frente al ensayo de referencia:</translation>
    </message>
</context>
<context>
    <name>ConsoleCommand</name>
    <message>
        <source>The record&apos;s own sample step [s] (a one-column file of values needs it).</source>
        <translation>Paso de muestreo propio del registro [s] (lo necesita un archivo de una sola columna de valores).</translation>
    </message>
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
        <translation>Controlador del actuador: builtin (por defecto) o tcp://HOST:PORT.</translation>
    </message>
    <message>
        <source>--controller: %1</source>
        <translation>--controller: %1</translation>
    </message>
</context>
<context>
    <name>ExportCommand</name>
    <message>
        <source>Write a run record (HDF5) as CSV files, one per group.</source>
        <translation>Escribe un registro de ensayo (HDF5) como archivos CSV, uno por grupo.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>El subcomando.</translation>
    </message>
    <message>
        <source>The record (record.h5).</source>
        <translation>El registro (record.h5).</translation>
    </message>
    <message>
        <source>Output directory for the CSVs.</source>
        <translation>Directorio de salida de los CSV.</translation>
    </message>
    <message>
        <source>expected exactly one FILE.h5</source>
        <translation>se esperaba exactamente un FILE.h5</translation>
    </message>
    <message>
        <source>missing --csv DIR</source>
        <translation>falta --csv DIR</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1: no se puede crear el directorio de salida</translation>
    </message>
    <message>
        <source>%1 steps, %2 alarms; written:</source>
        <translation>%1 pasos, %2 alarmas; escrito:</translation>
    </message>
    <message>
        <source>Units of the CSV columns, e.g. length=in,force=kip,rotation=deg,moment=kip*in,time=ms (length: m, cm, mm, in, ft; force: N, kN, MN, lbf, kip, kgf, tonf; rotation: rad, mrad, deg; moment: a force unit times a length unit; time: s, ms). Default: kN, m, s, rad.</source>
        <translation>Unidades de las columnas CSV, p. ej. length=in,force=kip,rotation=deg,moment=kip*in,time=ms (longitud: m, cm, mm, in, ft; fuerza: N, kN, MN, lbf, kip, kgf, tonf; rotación: rad, mrad, deg; momento: una unidad de fuerza por una de longitud; tiempo: s, ms). Por defecto: kN, m, s, rad.</translation>
    </message>
</context>
<context>
    <name>GroundMotionCheck</name>
    <message>
        <source>%1 is not a text file of numbers (it holds binary data, e.g. an image); expected a PEER AT2 record, two columns (time, acceleration) or one column of values</source>
        <translation>%1 no es un archivo de texto con números (contiene datos binarios, p. ej. una imagen); se espera un registro PEER AT2, dos columnas (tiempo, aceleración) o una columna de valores</translation>
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
    <message>
        <source>Time step [s] between the points of a one-column history (a rate-dependent law).</source>
        <translation>Paso de tiempo [s] entre los puntos de una historia de una columna (una ley que depende de la velocidad).</translation>
    </message>
    <message>
        <source>--dt &apos;%1&apos;: expected a time step &gt; 0 in seconds</source>
        <translation>--dt &apos;%1&apos;: se esperaba un paso de tiempo &gt; 0 en segundos</translation>
    </message>
    <message>
        <source>--dt: the history has its own time column</source>
        <translation>--dt: la historia tiene su propia columna de tiempo</translation>
    </message>
    <message>
        <source>%1 is rate-dependent: give the history a time column (time, deformation) or --dt</source>
        <translation>%1 depende de la velocidad: dé a la historia una columna de tiempo (tiempo, deformación) o --dt</translation>
    </message>
</context>
<context>
    <name>MethodComparisonTable</name>
    <message>
        <source>Method comparison on %1: %2 samples</source>
        <translation>Comparación de métodos en %1: %2 muestras</translation>
    </message>
    <message>
        <source>method</source>
        <translation>método</translation>
    </message>
    <message>
        <source>NRMSE [%]</source>
        <translation>NRMSE [%]</translation>
    </message>
    <message>
        <source>CPU [s]</source>
        <translation>CPU [s]</translation>
    </message>
    <message>
        <source>on bounds</source>
        <translation>en los límites</translation>
    </message>
    <message>
        <source>rejected</source>
        <translation>rechazadas</translation>
    </message>
    <message>
        <source>verdict</source>
        <translation>veredicto</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>  recommended: %1 (the cheapest within 5 % of the best NRMSE)</source>
        <translation>  recomendado: %1 (el más barato dentro del 5 % del mejor NRMSE)</translation>
    </message>
    <message>
        <source>  verdict: %1</source>
        <translation>  veredicto: %1</translation>
    </message>
    <message>
        <source>  outputs: %1 (comparison.csv, summary.json; each method&apos;s own files in calibration/, ukf/, nelder-mead/)</source>
        <translation>  salidas: %1 (comparison.csv, summary.json; los archivos de cada método en calibration/, ukf/, nelder-mead/)</translation>
    </message>
</context>
<context>
    <name>OperatorEvent</name>
    <message>
        <source>pre-flight confirmed by the operator (zero offsets)</source>
        <translation>comprobación previa confirmada por el operador (ceros)</translation>
    </message>
    <message>
        <source>test started by the operator</source>
        <translation>ensayo iniciado por el operador</translation>
    </message>
    <message>
        <source>paused by the operator</source>
        <translation>pausado por el operador</translation>
    </message>
    <message>
        <source>single step by the operator</source>
        <translation>paso único por el operador</translation>
    </message>
    <message>
        <source>resumed by the operator</source>
        <translation>reanudado por el operador</translation>
    </message>
    <message>
        <source>emergency hold before the test was armed: nothing is armed, the pre-flight check must be confirmed again</source>
        <translation>retención de emergencia antes de armar el ensayo: nada está armado, hay que confirmar de nuevo la comprobación previa</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>retención de emergencia por el operador</translation>
    </message>
    <message>
        <source>test ended by the operator, data kept</source>
        <translation>ensayo terminado por el operador, datos conservados</translation>
    </message>
    <message>
        <source>update %1 approved by the operator: %2 -&gt; %3</source>
        <translation>actualización %1 aprobada por el operador: %2 -&gt; %3</translation>
    </message>
    <message>
        <source>update %1 rejected by the operator (%2)</source>
        <translation>actualización %1 rechazada por el operador (%2)</translation>
    </message>
    <message>
        <source>offsets %1 approved by the operator for %2: %3</source>
        <translation>desplazamientos de cero %1 aprobados por el operador para %2: %3</translation>
    </message>
    <message>
        <source>offsets %1 rejected by the operator (%2)</source>
        <translation>desplazamientos de cero %1 rechazados por el operador (%2)</translation>
    </message>
    <message>
        <source>bounds changed: %1 -&gt; %2</source>
        <translation>límites cambiados: %1 -&gt; %2</translation>
    </message>
    <message>
        <source>lock changed: %1 -&gt; %2</source>
        <translation>bloqueo cambiado: %1 -&gt; %2</translation>
    </message>
    <message>
        <source>fit-error threshold changed: %1 -&gt; %2</source>
        <translation>umbral del error de ajuste cambiado: %1 -&gt; %2</translation>
    </message>
    <message>
        <source>updating policy changed: %1 -&gt; %2</source>
        <translation>política de actualización cambiada: %1 -&gt; %2</translation>
    </message>
    <message>
        <source>%1 (wall time %2)</source>
        <translation>%1 (hora real %2)</translation>
    </message>
    <message>
        <source>pre-flight check skipped: the test was started from the command line (--start)</source>
        <translation>verificación previa omitida: el ensayo se inició desde la línea de órdenes (--start)</translation>
    </message>
    <message>
        <source>note recorded: %1</source>
        <translation>nota registrada: %1</translation>
    </message>
    <message>
        <source>%1 (%L2 committed steps, last deformation %3 %4)</source>
        <translation>%1 (%L2 pasos confirmados, última deformación %3 %4)</translation>
    </message>
    <message>
        <source>specimen loaded by an earlier test: %1; the operator continues on it</source>
        <translation>probeta cargada por un ensayo anterior: %1; el operador continúa con ella</translation>
    </message>
    <message>
        <source>specimen loaded by an earlier test: %1; the operator chose a fresh specimen, its controller reset it to step 0</source>
        <translation>probeta cargada por un ensayo anterior: %1; el operador eligió una probeta nueva, su controlador la reinició al paso 0</translation>
    </message>
    <message>
        <source>specimen loaded by an earlier test: %1; the operator chose a fresh specimen, its controller refused (nothing changed)</source>
        <translation>probeta cargada por un ensayo anterior: %1; el operador eligió una probeta nueva, su controlador la rechazó (nada cambió)</translation>
    </message>
</context>
<context>
    <name>OverrideOptions</name>
    <message>
        <source>The record&apos;s own sample step [s] (a one-column file of values needs it).</source>
        <translation>Paso de muestreo propio del registro [s] (lo necesita un archivo de una sola columna de valores).</translation>
    </message>
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
        <translation>%1: formato de gráfica desconocido &apos;%2&apos; (se esperaba png, svg o pdf)</translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation>%1: no se pudo escribir la gráfica</translation>
    </message>
</context>
<context>
    <name>PreflightChecks</name>
    <message>
        <source>time step dt [s]</source>
        <translation>paso de tiempo dt [s]</translation>
    </message>
    <message>
        <source>duration [s]</source>
        <translation>duración [s]</translation>
    </message>
    <message>
        <source>ground motion</source>
        <translation>movimiento del suelo</translation>
    </message>
    <message>
        <source>ground motion scale [-]</source>
        <translation>escala del movimiento del suelo [-]</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>integrador</translation>
    </message>
    <message>
        <source>controller</source>
        <translation>controlador</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <source>PGA [m/s²]</source>
        <translation>PGA [m/s²]</translation>
    </message>
    <message>
        <source>Unusual step count: %L1 steps (more than %L2); check dt and the duration.</source>
        <translation>Número de pasos inusual: %L1 pasos (más de %L2); revise dt y la duración.</translation>
    </message>
    <message>
        <source>Unusual PGA: %1 m/s² (above %2 m/s²); check the ground motion scale.</source>
        <translation>PGA inusual: %1 m/s² (más de %2 m/s²); revise la escala del movimiento del suelo.</translation>
    </message>
    <message>
        <source>The ground motion is zero (PGA 0 m/s²).</source>
        <translation>El movimiento del suelo es nulo (PGA 0 m/s²).</translation>
    </message>
    <message>
        <source>Very small time step: dt = %1 s.</source>
        <translation>Paso de tiempo muy pequeño: dt = %1 s.</translation>
    </message>
    <message>
        <source>Changed since the last run: %1 %2 -&gt; %3</source>
        <translation>Cambiado desde el último ensayo: %1 %2 -&gt; %3</translation>
    </message>
</context>
<context>
    <name>PreflightDialog</name>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
</context>
<context>
    <name>ReplayCommand</name>
    <message>
        <source>Re-identify a recorded specimen, or imported measured data, offline.</source>
        <translation>Vuelve a identificar fuera de línea una probeta registrada o datos medidos importados.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>El subcomando.</translation>
    </message>
    <message>
        <source>A run record (record.h5).</source>
        <translation>Un registro de ensayo (record.h5).</translation>
    </message>
    <message>
        <source>Re-run the identification headless.</source>
        <translation>Repite la identificación sin interfaz gráfica.</translation>
    </message>
    <message>
        <source>JSON with &quot;model&quot; and/or &quot;updating&quot; settings to override.</source>
        <translation>JSON con los ajustes &quot;model&quot; y/o &quot;updating&quot; que se sobrescriben.</translation>
    </message>
    <message>
        <source>The recorded specimen to identify.</source>
        <translation>La probeta registrada que se identifica.</translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation>Directorio de salida.</translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>argumento inesperado &apos;%1&apos;</translation>
    </message>
    <message>
        <source>give either FILE.h5 or --import DATA.csv, not both</source>
        <translation>indique FILE.h5 o --import DATA.csv, no ambos</translation>
    </message>
    <message>
        <source>expected FILE.h5 (a run record) or --import DATA.csv</source>
        <translation>se esperaba FILE.h5 (un registro de ensayo) o --import DATA.csv</translation>
    </message>
    <message>
        <source>--units applies to --import only (a record has its units)</source>
        <translation>--units solo se aplica a --import (un registro tiene sus propias unidades)</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>falta --out DIR</translation>
    </message>
    <message>
        <source>%1 identification of %2: %3 samples, dt %4 s</source>
        <translation>identificación %1 de %2: %3 muestras, dt %4 s</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>parámetro</translation>
    </message>
    <message>
        <source>initial</source>
        <translation>inicial</translation>
    </message>
    <message>
        <source>final</source>
        <translation>final</translation>
    </message>
    <message>
        <source>std</source>
        <translation>desv. est.</translation>
    </message>
    <message>
        <source>online</source>
        <translation>en línea</translation>
    </message>
    <message>
        <source>  Nelder-Mead fits accepted: %1</source>
        <translation>  ajustes de Nelder-Mead aceptados: %1</translation>
    </message>
    <message>
        <source>  estimator warnings: %1 (see summary.json)</source>
        <translation>  advertencias del estimador: %1 (véase summary.json)</translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation>  salidas: %1</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1: no se puede crear el directorio de salida</translation>
    </message>
    <message>
        <source>Measured data: CSV or text of time (or a sample index), deformation, force with units.</source>
        <translation>Datos medidos: CSV o texto de tiempo (o un índice de muestra), deformación y fuerza con unidades.</translation>
    </message>
    <message>
        <source>Units of the imported columns time,deformation,force, e.g. s,mm,kN (time: s, ms or step; deformation: m, cm, mm, in, ft, rad, mrad, deg; force: N, kN, MN, lbf, kip, kgf, tonf, g or a moment such as kN*m, kip*in).</source>
        <translation>Unidades de las columnas importadas tiempo,deformación,fuerza, p. ej. s,mm,kN (tiempo: s, ms o step; deformación: m, cm, mm, in, ft, rad, mrad, deg; fuerza: N, kN, MN, lbf, kip, kgf, tonf, g o un momento como kN*m, kip*in).</translation>
    </message>
    <message>
        <source>Positions (from 1) of the imported time, deformation and force columns, e.g. 1,2,3; other columns are ignored.</source>
        <translation>Posiciones (desde 1) de las columnas importadas de tiempo, deformación y fuerza, p. ej. 1,2,3; las demás columnas se ignoran.</translation>
    </message>
    <message>
        <source>--columns applies to --import only</source>
        <translation>--columns solo se aplica a --import</translation>
    </message>
    <message>
        <source>  calibration over the whole history (%1 starts, %2 s): NRMSE %3 %</source>
        <translation>  calibración sobre toda la historia (%1 puntos de partida, %2 s): NRMSE %3 %</translation>
    </message>
    <message>
        <source>on its bound</source>
        <translation>en su límite</translation>
    </message>
    <message>
        <source>  verdict: %1</source>
        <translation>  veredicto: %1</translation>
    </message>
    <message>
        <source>uRef %1 %2, fRef %3 %4</source>
        <translation>uRef %1 %2, fRef %3 %4</translation>
    </message>
    <message>
        <source>  normalized units (x = u / uRef, f = F / fRef), final model&apos;s scales: %1</source>
        <translation>  unidades normalizadas (x = u / uRef, f = F / fRef), escalas del modelo final: %1</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>unidad</translation>
    </message>
    <message>
        <source>  final model over the whole history: RMS force error %1 %2 (NRMSE %3 %; the initial model&apos;s %4 %)</source>
        <translation>  modelo final sobre toda la historia: error RMS de fuerza %1 %2 (NRMSE %3 %; el del modelo inicial %4 %)</translation>
    </message>
    <message>
        <source>  online model&apos;s prediction over the record (each sample with the estimate known before it): NRMSE %1 %</source>
        <translation>  predicción del modelo en línea sobre el registro (cada muestra con la estimación conocida antes de ella): NRMSE %1 %</translation>
    </message>
    <message>
        <source>  warning: %1</source>
        <translation>  aviso: %1</translation>
    </message>
    <message>
        <source>    in the same scales: %1</source>
        <translation>    en las mismas escalas: %1</translation>
    </message>
    <message>
        <source>    in its own scales: %1 (its normalized values are not comparable with the table&apos;s above)</source>
        <translation>    en sus propias escalas: %1 (sus valores normalizados no son comparables con los de la tabla anterior)</translation>
    </message>
    <message>
        <source>The calibration&apos;s deformation and force offsets: auto (fitted when the data ask for them, the default), on or off.</source>
        <translation>Los desplazamientos de cero (offsets) de deformación y de fuerza de la calibración: auto (ajustados cuando los datos los piden, por defecto), on u off.</translation>
    </message>
    <message>
        <source>--offsets: expected auto, on or off, found &apos;%1&apos;</source>
        <translation>--offsets: se esperaba auto, on u off; se encontró &apos;%1&apos;</translation>
    </message>
    <message>
        <source>    offsets fitted: NRMSE %1 % with them, %2 % without (criterion %3 &lt; 0 over %4 branches)</source>
        <translation>    offsets ajustados: NRMSE %1 % con ellos, %2 % sin ellos (criterio %3 &lt; 0 sobre %4 ramas)</translation>
    </message>
    <message>
        <source>    offsets not needed: NRMSE %1 % with them, %2 % without (criterion %3 &gt;= 0 over %4 branches)</source>
        <translation>    offsets innecesarios: NRMSE %1 % con ellos, %2 % sin ellos (criterio %3 &gt;= 0 sobre %4 ramas)</translation>
    </message>
    <message>
        <source>hsmu replay: %1 / %2 samples, %3 refits, %4 rejected, %5 s elapsed, about %6 s left</source>
        <translation>hsmu replay: %1 / %2 muestras, %3 reajustes, %4 rechazadas, %5 s transcurridos, quedan unos %6 s</translation>
    </message>
    <message>
        <source>hsmu replay: %1 (%2 s elapsed)</source>
        <translation>hsmu replay: %1 (%2 s transcurridos)</translation>
    </message>
    <message>
        <source>calibrating over the whole history</source>
        <translation>calibrando sobre toda la historia</translation>
    </message>
    <message>
        <source>final fit over the whole history</source>
        <translation>ajuste final sobre toda la historia</translation>
    </message>
    <message>
        <source>ukf, nelder-mead, calibration (only the whole-history fit) or all (the three, compared in one table).</source>
        <translation>ukf, nelder-mead, calibration (solo el ajuste de toda la historia) o all (los tres, comparados en una tabla).</translation>
    </message>
    <message>
        <source>hsmu replay: calibrating over the whole history (minimization %1 of %2, %3 s elapsed)</source>
        <translation>hsmu replay: calibrando sobre toda la historia (minimización %1 de %2, %3 s transcurridos)</translation>
    </message>
    <message>
        <source>%1 identification of %2 interrupted (%3) during the %4: %5 / %6 samples done, %7 refits, %8 rejected</source>
        <translation>identificación %1 de %2 interrumpida (%3) durante %4: %5 / %6 muestras hechas, %7 reajustes, %8 rechazadas</translation>
    </message>
    <message>
        <source>online pass</source>
        <translation>la pasada en línea</translation>
    </message>
    <message>
        <source>calibration</source>
        <translation>la calibración</translation>
    </message>
    <message>
        <source>final fit</source>
        <translation>el ajuste final</translation>
    </message>
    <message>
        <source>  no estimate yet</source>
        <translation>  aún sin estimación</translation>
    </message>
    <message>
        <source>  parameters after sample %1:</source>
        <translation>  parámetros tras la muestra %1:</translation>
    </message>
    <message>
        <source>  partial summary: %1</source>
        <translation>  resumen parcial: %1</translation>
    </message>
</context>
<context>
    <name>ReplayExport</name>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: no se puede escribir (%2)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>ReplayWindowCommand</name>
    <message>
        <source>Replay a recorded test (an HDF5 run record) in a window.</source>
        <translation>Reproduce en una ventana un ensayo registrado (un registro de ensayo HDF5).</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>El subcomando.</translation>
    </message>
    <message>
        <source>The run record (record.h5).</source>
        <translation>El registro del ensayo (record.h5).</translation>
    </message>
    <message>
        <source>Test seconds per wall second (default 1).</source>
        <translation>Segundos de ensayo por segundo real (por defecto 1).</translation>
    </message>
    <message>
        <source>Start playing at once.</source>
        <translation>Empieza a reproducir de inmediato.</translation>
    </message>
    <message>
        <source>Grab the window into this PNG file, then quit.</source>
        <translation>Captura la ventana en este archivo PNG y luego sale.</translation>
    </message>
    <message>
        <source>Seconds before the screenshot (default 3).</source>
        <translation>Segundos antes de la captura (por defecto 3).</translation>
    </message>
    <message>
        <source>expected one record file: hsmu replay FILE.h5</source>
        <translation>se esperaba un archivo de registro: hsmu replay FILE.h5</translation>
    </message>
    <message>
        <source>--speed: expected a positive number</source>
        <translation>--speed: se esperaba un número positivo</translation>
    </message>
    <message>
        <source>--screenshot-after: expected a number of seconds</source>
        <translation>--screenshot-after: se esperaba un número de segundos</translation>
    </message>
</context>
<context>
    <name>RthsCommand</name>
    <message>
        <source>the controller did not resume the run: %1</source>
        <translation>el controlador no reanudó el ensayo: %1</translation>
    </message>
    <message>
        <source>With --controller: resume the controller&apos;s held run from the tick where it held instead of starting one.</source>
        <translation>Con --controller: reanudar el ensayo detenido del controlador desde el ciclo en que se detuvo en lugar de iniciar uno.</translation>
    </message>
    <message>
        <source>--resume needs --controller: it resumes the held run hsmu-controller keeps (a local run is resumed in the console&apos;s RTHS view)</source>
        <translation>--resume necesita --controller: reanuda el ensayo detenido que conserva hsmu-controller (un ensayo local se reanuda en la vista RTHS de la consola)</translation>
    </message>
    <message>
        <source>Real-time hybrid simulation on the virtual lab&apos;s servo-hydraulic actuator.</source>
        <translation>Simulación híbrida en tiempo real con el actuador servohidráulico del laboratorio virtual.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>El subcomando.</translation>
    </message>
    <message>
        <source>A configuration file or rths-benchmark-case-1 .. -4.</source>
        <translation>Un archivo de configuración o rths-benchmark-case-1 .. -4.</translation>
    </message>
    <message>
        <source>Output folder.</source>
        <translation>Carpeta de salida.</translation>
    </message>
    <message>
        <source>Ground-motion record (m/s^2 unless the configuration says).</source>
        <translation>Registro sísmico (m/s^2 salvo que la configuración diga otra cosa).</translation>
    </message>
    <message>
        <source>Scale of the record.</source>
        <translation>Factor de escala del registro.</translation>
    </message>
    <message>
        <source>Stop after T seconds.</source>
        <translation>Detener tras T segundos.</translation>
    </message>
    <message>
        <source>fast (simulated, default) or realtime (wall clock).</source>
        <translation>fast (simulado, por defecto) o realtime (reloj real).</translation>
    </message>
    <message>
        <source>Run the loop&apos;s thread under SCHED_FIFO (with --pace realtime).</source>
        <translation>Ejecutar el hilo del lazo con SCHED_FIFO (con --pace realtime).</translation>
    </message>
    <message>
        <source>default, none, lead, polynomial, feedforward or ats.</source>
        <translation>default, none, lead, polynomial, feedforward o ats.</translation>
    </message>
    <message>
        <source>Draw the plant from the benchmark&apos;s distributions with this seed.</source>
        <translation>Sortear la planta de las distribuciones del benchmark con esta semilla.</translation>
    </message>
    <message>
        <source>With --pace realtime: busy-wait the last N microseconds before each release (default: a quarter of the period, at most 100; 0: sleep only).</source>
        <translation>Con --pace realtime: espera activa durante los últimos N microsegundos antes de cada liberación (por defecto: un cuarto del periodo, como máximo 100; 0: solo dormir).</translation>
    </message>
    <message>
        <source>--spin-us: expected 0 up to the loop period (%1 us), got &apos;%2&apos;</source>
        <translation>--spin-us: se esperaba de 0 hasta el periodo del lazo (%1 us), se obtuvo &apos;%2&apos;</translation>
    </message>
    <message>
        <source>Check this computer instead of running: release S seconds of empty ticks at the configuration&apos;s loop rate (with --realtime-priority and --spin-us as a run would) and report how late they come.</source>
        <translation>Comprobar este ordenador en lugar de ejecutar: liberar S segundos de ticks vacíos a la frecuencia del lazo de la configuración (con --realtime-priority y --spin-us como lo haría una ejecución) e informar de su retraso.</translation>
    </message>
    <message>
        <source>--probe-host checks this computer: run it on the controller&apos;s computer without --controller</source>
        <translation>--probe-host comprueba este ordenador: ejecútelo en el ordenador del controlador sin --controller</translation>
    </message>
    <message>
        <source>--probe-host: expected seconds in (0, 3600], got &apos;%1&apos;</source>
        <translation>--probe-host: se esperaban segundos en (0, 3600], se obtuvo &apos;%1&apos;</translation>
    </message>
    <message>
        <source>hsmu rths: real-time priority not taken (%1); the probe ran at normal priority</source>
        <translation>hsmu rths: no se obtuvo la prioridad de tiempo real (%1); la prueba se ejecutó con prioridad normal</translation>
    </message>
    <message>
        <source>host probe at %1 Hz (spin %2 us%3): %4</source>
        <translation>prueba del ordenador a %1 Hz (espera activa %2 us%3): %4</translation>
    </message>
    <message>
        <source>, SCHED_FIFO 80</source>
        <translation>, SCHED_FIFO 80</translation>
    </message>
    <message>
        <source>Sensor noise seed.</source>
        <translation>Semilla del ruido de los sensores.</translation>
    </message>
    <message>
        <source>Sensors without noise.</source>
        <translation>Sensores sin ruido.</translation>
    </message>
    <message>
        <source>expected one CONFIG (a file or rths-benchmark-case-1 .. -4)</source>
        <translation>se esperaba un CONFIG (un archivo o rths-benchmark-case-1 .. -4)</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>falta --out DIR</translation>
    </message>
    <message>
        <source>--pace: expected fast or realtime, got &apos;%1&apos;</source>
        <translation>--pace: se esperaba fast o realtime, se recibió &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--compensation: expected default, none, lead, polynomial, feedforward or ats, got &apos;%1&apos;</source>
        <translation>--compensation: se esperaba default, none, lead, polynomial, feedforward o ats, se recibió &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--seed, --scale and --duration take numbers</source>
        <translation>--seed, --scale y --duration requieren números</translation>
    </message>
    <message>
        <source>--perturb takes a seed</source>
        <translation>--perturb requiere una semilla</translation>
    </message>
    <message>
        <source>no ground motion: give --ground-motion FILE</source>
        <translation>no hay registro sísmico: indique --ground-motion ARCHIVO</translation>
    </message>
    <message>
        <source>%1: the ground-motion record does not exist (give --ground-motion FILE)</source>
        <translation>%1: el registro sísmico no existe (indique --ground-motion ARCHIVO)</translation>
    </message>
    <message>
        <source>%1: %2 Hz loop, compensation %3%4</source>
        <translation>%1: lazo de %2 Hz, compensación %3%4</translation>
    </message>
    <message>
        <source> + phase lead</source>
        <translation> + adelanto de fase</translation>
    </message>
    <message>
        <source>pre-flight: %1</source>
        <translation>verificación previa: %1</translation>
    </message>
    <message>
        <source>refused in pre-flight: %1</source>
        <translation>rechazado en la verificación previa: %1</translation>
    </message>
    <message>
        <source>%1: cannot create the output folder</source>
        <translation>%1: no se puede crear la carpeta de salida</translation>
    </message>
    <message>
        <source>hsmu rths: real-time priority not taken (%1); the loop ran at normal priority</source>
        <translation>hsmu rths: no se obtuvo la prioridad de tiempo real (%1); el lazo corrió con prioridad normal</translation>
    </message>
    <message>
        <source>%1 ticks (%2 s); %3</source>
        <translation>%1 ciclos (%2 s); %3</translation>
    </message>
    <message>
        <source>frequency evaluation: amplitude %1, delay %2 ms at %3 Hz; tracking indicator %4 m^2</source>
        <translation>evaluación en frecuencia: amplitud %1, retardo %2 ms a %3 Hz; indicador de seguimiento %4 m^2</translation>
    </message>
    <message>
        <source>deadline misses: %1 (worst %2 us late)</source>
        <translation>plazos incumplidos: %1 (el peor con %2 us de retraso)</translation>
    </message>
    <message>
        <source>outputs: %1/record.h5, %1/steps.csv, %1/summary.json</source>
        <translation>salidas: %1/record.h5, %1/steps.csv, %1/summary.json</translation>
    </message>
    <message>
        <source>hsmu rths: %1</source>
        <translation>hsmu rths: %1</translation>
    </message>
    <message>
        <source>Monitor the loop run by hsmu-controller --rths at tcp://HOST:PORT.</source>
        <translation>Supervisar el lazo que ejecuta hsmu-controller --rths en tcp://HOST:PORT.</translation>
    </message>
    <message>
        <source>File whose first line is the controller&apos;s shared secret.</source>
        <translation>Archivo cuya primera línea es el secreto compartido del controlador.</translation>
    </message>
    <message>
        <source>With --controller: one telemetry frame every N ticks (default: about 128 per second).</source>
        <translation>Con --controller: una trama de telemetría cada N ciclos (por defecto: unas 128 por segundo).</translation>
    </message>
    <message>
        <source>--%1 does not apply with --controller: the controller runs the loop of its own copy of the configuration</source>
        <translation>--%1 no se aplica con --controller: el controlador ejecuta el lazo de su propia copia de la configuración</translation>
    </message>
    <message>
        <source>--controller: %1</source>
        <translation>--controller: %1</translation>
    </message>
    <message>
        <source>--controller: an RTHS loop is monitored over tcp://HOST:PORT (hsmu-controller --rths)</source>
        <translation>--controller: un lazo RTHS se supervisa mediante tcp://HOST:PORT (hsmu-controller --rths)</translation>
    </message>
    <message>
        <source>--token-file: %1</source>
        <translation>--token-file: %1</translation>
    </message>
    <message>
        <source>--telemetry-every: expected a whole number &gt;= 1, got &apos;%1&apos;</source>
        <translation>--telemetry-every: se esperaba un número entero &gt;= 1, se obtuvo &apos;%1&apos;</translation>
    </message>
    <message>
        <source>With --controller: at T seconds of the run, send new values of the damper twin&apos;s parameters (repeatable).</source>
        <translation>Con --controller: a los T segundos del ensayo, envía nuevos valores de los parámetros del gemelo del amortiguador (repetible).</translation>
    </message>
    <message>
        <source>--update: expected T:NAME=VALUE[,NAME=VALUE...] (seconds, then the damper twin&apos;s parameters), got &apos;%1&apos;</source>
        <translation>--update: se esperaba T:NOMBRE=VALOR[,NOMBRE=VALOR...] (segundos, luego los parámetros del gemelo del amortiguador), se obtuvo &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--update needs --controller: it sends the update to the loop hsmu-controller runs</source>
        <translation>--update necesita --controller: envía la actualización al lazo que ejecuta hsmu-controller</translation>
    </message>
    <message>
        <source>%1/telemetry.csv: cannot be written</source>
        <translation>%1/telemetry.csv: no se puede escribir</translation>
    </message>
    <message>
        <source>cannot reach the controller %1:%2: %3</source>
        <translation>no se puede alcanzar el controlador %1:%2: %3</translation>
    </message>
    <message>
        <source>the controller refused the monitor: %1</source>
        <translation>el controlador rechazó el monitor: %1</translation>
    </message>
    <message>
        <source>controller: %1</source>
        <translation>controlador: %1</translation>
    </message>
    <message>
        <source>the link to the controller was lost: %1 (the controller holds the loop per its --monitor-loss policy); %2 telemetry frames in %3/telemetry.csv</source>
        <translation>se perdió el enlace con el controlador: %1 (el controlador detiene el lazo según su política --monitor-loss); %2 tramas de telemetría en %3/telemetry.csv</translation>
    </message>
    <message>
        <source>t = %1 s: desired %2 mm, measured %3 mm, %4 deadline misses</source>
        <translation>t = %1 s: deseado %2 mm, medido %3 mm, %4 plazos incumplidos</translation>
    </message>
    <message>
        <source>the controller: %1</source>
        <translation>el controlador: %1</translation>
    </message>
    <message>
        <source>%1 ticks on the controller; %2</source>
        <translation>%1 ciclos en el controlador; %2</translation>
    </message>
    <message>
        <source>deadline misses: %1 (worst %2 us late); telemetry %3 received, %4 dropped</source>
        <translation>plazos incumplidos: %1 (el peor con %2 us de retraso); telemetría: %3 recibidas, %4 descartadas</translation>
    </message>
    <message>
        <source>outputs: %1/telemetry.csv, %1/summary.json</source>
        <translation>salidas: %1/telemetry.csv, %1/summary.json</translation>
    </message>
</context>
<context>
    <name>RunCommand</name>
    <message>
        <source>%1 %  t = %2 s  %3 steps/s</source>
        <translation>%1 %  t = %2 s  %3 pasos/s</translation>
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
        <source>%1: write failed</source>
        <translation>%1: error de escritura</translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation>%1: no se pudo escribir la gráfica</translation>
    </message>
    <message>
        <source>hsmu run: connecting to %1 (%2 protocol, %3)</source>
        <translation>hsmu run: conectando con %1 (protocolo %2, %3)</translation>
    </message>
    <message>
        <source>hsmu run: steps.csv not written (%1 columns); record.h5 holds every column (hsmu export writes CSV from it)</source>
        <translation>hsmu run: steps.csv no se escribe (%1 columnas); record.h5 guarda todas las columnas (hsmu export escribe CSV a partir de él)</translation>
    </message>
    <message>
        <source>hsmu run: link fault at t = %1 s (step %2): %3; reconnecting in %4 s (attempt %5 of %6)</source>
        <translation>hsmu run: fallo del enlace en t = %1 s (paso %2): %3; reconectando en %4 s (intento %5 de %6)</translation>
    </message>
    <message>
        <source>--plots: this program cannot draw (run it through hsmu)</source>
        <translation>--plots: este programa no puede dibujar (ejecútelo a través de hsmu)</translation>
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
        <source>File whose first line is the controller&apos;s shared secret (readable by you only; else the environment variable HSMU_CONTROLLER_TOKEN).</source>
        <translation>Archivo cuya primera línea es el secreto compartido con el controlador (legible solo por usted; si no, la variable de entorno HSMU_CONTROLLER_TOKEN).</translation>
    </message>
    <message>
        <source>--token is not accepted: arguments show in ps; put the token in a file (--token-file FILE) or in the environment variable HSMU_CONTROLLER_TOKEN</source>
        <translation>--token no se acepta: los argumentos se ven en ps; ponga el token en un archivo (--token-file ARCHIVO) o en la variable de entorno HSMU_CONTROLLER_TOKEN</translation>
    </message>
    <message>
        <source>--token-file: %1</source>
        <translation>--token-file: %1</translation>
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
        <translation>Controlador del actuador: builtin (probetas virtuales en el propio proceso, por defecto), tcp://HOST:PORT (hsmu-controller o un controlador de laboratorio, con el controller.protocol de la configuración, native por defecto), simapp://HOST:PORT (un servidor SimApp de OpenFresco) o generictcp://HOST:PORT (un servidor para el GenericTCP de OpenFresco).</translation>
    </message>
    <message>
        <source>steps.csv: auto (written when a row has at most 200 values, the default), all or none; record.h5 holds every column either way.</source>
        <translation>steps.csv: auto (se escribe cuando una fila tiene como máximo 200 valores, por defecto), all o none; record.h5 guarda todas las columnas en cualquier caso.</translation>
    </message>
    <message>
        <source>Compress the record&apos;s per-step matrices: deflate level 1-9 with shuffle (default 0: uncompressed).</source>
        <translation>Comprime las matrices por paso del registro: nivel de deflate 1-9 con shuffle (por defecto 0: sin comprimir).</translation>
    </message>
    <message>
        <source>--csv: expected auto, all or none, found &apos;%1&apos;</source>
        <translation>--csv: se esperaba auto, all o none, se encontró &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--compress: expected a whole number from 0 to 9, found &apos;%1&apos;</source>
        <translation>--compress: se esperaba un número entero de 0 a 9, se encontró &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Numerical DOFs the record keeps: indices, ranges and names, e.g. 0-9,100,Roof (default: every DOF). A specimen&apos;s channels are always recorded in full.</source>
        <translation>DOF numéricos que guarda el registro: índices, rangos y nombres, p. ej. 0-9,100,Roof (por defecto: todos los DOF). Los canales de un espécimen se registran siempre completos.</translation>
    </message>
    <message>
        <source>Keep the numerical DOFs&apos; rows of every N-th step only (default 1). A specimen&apos;s channels are always recorded at every step.</source>
        <translation>Guarda las filas de los DOF numéricos solo cada N pasos (por defecto 1). Los canales de un espécimen se registran siempre en cada paso.</translation>
    </message>
    <message>
        <source>--record-every: expected a whole number from 1 to %1, found &apos;%2&apos;</source>
        <translation>--record-every: se esperaba un número entero de 1 a %1, se encontró &apos;%2&apos;</translation>
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
        <source>  tracking of %1 (commanded against measured): J1 %2 ms, J2 %3 %, J3 %4 %</source>
        <translation>  seguimiento de %1 (ordenado frente a medido): J1 %2 ms, J2 %3 %, J3 %4 %</translation>
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
    <message>
        <source>  record: DOFs %1 (%2 of %3), every %4 steps; elements, specimens and updating at every step</source>
        <translation>  registro: DOF %1 (%2 de %3), cada %4 pasos; elementos, especímenes y actualización en cada paso</translation>
    </message>
    <message>
        <source>... %1 more in summary.json</source>
        <translation>... %1 más en summary.json</translation>
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
    <name>hsmu::gui::ActuatorsPanel</name>
    <message>
        <source>Displacement [%1]</source>
        <translation>Desplazamiento [%1]</translation>
    </message>
    <message>
        <source>Rotation [%1]</source>
        <translation>Rotación [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation>Fuerza [%1]</translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation>Momento [%1]</translation>
    </message>
    <message>
        <source>axial</source>
        <translation>axial</translation>
    </message>
    <message>
        <source>shear</source>
        <translation>cortante</translation>
    </message>
    <message>
        <source>rotation</source>
        <translation>rotación</translation>
    </message>
    <message>
        <source>commanded</source>
        <translation>comandado</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>medido</translation>
    </message>
    <message>
        <source>command</source>
        <translation>comando</translation>
    </message>
    <message>
        <source>stroke</source>
        <translation>carrera</translation>
    </message>
    <message>
        <source>force</source>
        <translation>fuerza</translation>
    </message>
    <message>
        <source>%1: %2 DOF</source>
        <translation>%1: GDL %2</translation>
    </message>
    <message>
        <source>%1: actuator &apos;%2&apos;</source>
        <translation>%1: actuador &apos;%2&apos;</translation>
    </message>
    <message>
        <source>%1: every basic deformation</source>
        <translation>%1: todas las deformaciones básicas</translation>
    </message>
    <message>
        <source>%1: every basic force</source>
        <translation>%1: todas las fuerzas básicas</translation>
    </message>
    <message>
        <source>%1: every actuator&apos;s stroke</source>
        <translation>%1: la carrera de cada actuador</translation>
    </message>
    <message>
        <source>%1: every actuator&apos;s force</source>
        <translation>%1: la fuerza de cada actuador</translation>
    </message>
    <message>
        <source>The actuator, basic DOF or set of channels the plot shows</source>
        <translation>El actuador, GDL básico o conjunto de canales que muestra el gráfico</translation>
    </message>
    <message>
        <source>No step yet.</source>
        <translation>Aún no hay pasos.</translation>
    </message>
    <message>
        <source>Step %1, t = %2 s: %3</source>
        <translation>Paso %1, t = %2 s: %3</translation>
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
        <translation>Tiempo [s]</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Paso</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Gravedad</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Mensaje</translation>
    </message>
    <message>
        <source>Acknowledged</source>
        <translation>Reconocida</translation>
    </message>
    <message>
        <source>console</source>
        <translation>consola</translation>
    </message>
    <message>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <source>yes, %1</source>
        <translation>sí, %1</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: no se puede escribir (%2)</translation>
    </message>
    <message>
        <source>Copy the list</source>
        <translation>Copiar la lista</translation>
    </message>
    <message>
        <source>Copy selected rows</source>
        <translation>Copiar las filas seleccionadas</translation>
    </message>
    <message>
        <source>Export the list as CSV...</source>
        <translation>Exportar la lista como CSV...</translation>
    </message>
    <message>
        <source>Export alarms and events</source>
        <translation>Exportar alarmas y eventos</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::AlarmPanel</name>
    <message>
        <source>Acknowledge selected</source>
        <translation>Reconocer seleccionadas</translation>
    </message>
    <message>
        <source>Acknowledge all</source>
        <translation>Reconocer todas</translation>
    </message>
    <message>
        <source>Critical alarms stay red until acknowledged (double-click or the buttons).</source>
        <translation>Las alarmas críticas permanecen en rojo hasta que se reconocen (doble clic o los botones).</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::AttentionBanner</name>
    <message>
        <source>Acknowledge all</source>
        <translation>Reconocer todas</translation>
    </message>
    <message numerus="yes">
        <source>%n critical alarm(s) not acknowledged. Latest: %1</source>
        <translation>
            <numerusform>%n alarma crítica sin reconocer. Última: %1</numerusform>
            <numerusform>%n alarmas críticas sin reconocer. Última: %1</numerusform>
        </translation>
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
        <translation>Un solo paso</translation>
    </message>
    <message>
        <source>Emergency hold (%1)</source>
        <translation>Retención de emergencia (%1)</translation>
    </message>
    <message>
        <source>Hold the test at once, between two steps (%1)</source>
        <translation>Retiene el ensayo de inmediato, entre dos pasos (%1)</translation>
    </message>
    <message>
        <source>Stop...</source>
        <translation>Detener...</translation>
    </message>
    <message>
        <source>1/%1 x real time</source>
        <translation>1/%1 x tiempo real</translation>
    </message>
    <message>
        <source>fixed wall time per step</source>
        <translation>tiempo real fijo por paso</translation>
    </message>
    <message>
        <source>Each step takes this long in wall time (pseudo-dynamic pace)</source>
        <translation>Cada paso dura este tiempo real (ritmo pseudodinámico)</translation>
    </message>
    <message>
        <source> s/step</source>
        <translation> s/paso</translation>
    </message>
    <message>
        <source>Start the test after the pre-flight check (%1)</source>
        <translation>Iniciar el ensayo tras la verificación previa (%1)</translation>
    </message>
    <message>
        <source>Pause between two steps (%1)</source>
        <translation>Pausar entre dos pasos (%1)</translation>
    </message>
    <message>
        <source>Run exactly one integration step, then stay paused (%1)</source>
        <translation>Ejecutar exactamente un paso de integración y quedar en pausa (%1)</translation>
    </message>
    <message>
        <source>Continue the test (%1)</source>
        <translation>Continuar el ensayo (%1)</translation>
    </message>
    <message>
        <source>End the test, keeping the data (asks for confirmation; %1)</source>
        <translation>Terminar el ensayo conservando los datos (pide confirmación; %1)</translation>
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
        <translation>Historia de fuerza</translation>
    </message>
    <message>
        <source>Moment history</source>
        <translation>Historia de momento</translation>
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
        <source>Tracking of %1</source>
        <translation>Seguimiento de %1</translation>
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
        <source>commanded</source>
        <translation>ordenado</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>medido</translation>
    </message>
    <message>
        <source>Inspector fit error</source>
        <translation>Error de ajuste del inspector</translation>
    </message>
    <message>
        <source>Fit error [-]</source>
        <translation>Error de ajuste [-]</translation>
    </message>
    <message>
        <source>fit error</source>
        <translation>error de ajuste</translation>
    </message>
    <message>
        <source>actuator command</source>
        <translation>orden del actuador</translation>
    </message>
    <message>
        <source>held ticks</source>
        <translation>ciclos retenidos</translation>
    </message>
    <message>
        <source>Held ticks [-]</source>
        <translation>Ciclos retenidos [-]</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::HysteresisPlot</name>
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
        <translation>modelo auxiliar (%1)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::LivePlotsPanel</name>
    <message>
        <source>Dashed: %1</source>
        <translation>Discontinua: %1</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Imagen PNG (*.png)</translation>
    </message>
    <message>
        <source>SVG drawing (*.svg)</source>
        <translation>Dibujo SVG (*.svg)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>Documento PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Export this plot...</source>
        <translation>Exportar esta gráfica...</translation>
    </message>
    <message>
        <source>Export all plots...</source>
        <translation>Exportar todas las gráficas...</translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation>Exportar gráfica</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Error al exportar</translation>
    </message>
    <message>
        <source>Export all plots to</source>
        <translation>Exportar todas las gráficas a</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::MainWindow</name>
    <message>
        <source>Enter the record&apos;s sample step below the file.</source>
        <translation>Indique el paso de muestreo del registro debajo del archivo.</translation>
    </message>
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
        <source>Test setup</source>
        <translation>Configuración del ensayo</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parámetros</translation>
    </message>
    <message>
        <source>Pending updates</source>
        <translation>Actualizaciones pendientes</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>&amp;Open configuration...</source>
        <translation>&amp;Abrir configuración...</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>Abrir &amp;reciente</translation>
    </message>
    <message>
        <source>Open r&amp;ecord...</source>
        <translation>Abrir r&amp;egistro...</translation>
    </message>
    <message>
        <source>&amp;Settings...</source>
        <translation>&amp;Preferencias...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(ninguno)</translation>
    </message>
    <message>
        <source>setup not applied: %1</source>
        <translation>configuración no aplicada: %1</translation>
    </message>
    <message>
        <source>preparing the test (pre-flight)...</source>
        <translation>preparando el ensayo (comprobación previa)...</translation>
    </message>
    <message>
        <source>start cancelled at the pre-flight check</source>
        <translation>inicio cancelado en la comprobación previa</translation>
    </message>
    <message>
        <source>Add &amp;note...</source>
        <translation>Añadir &amp;nota...</translation>
    </message>
    <message>
        <source>Record a note at the current step of the test</source>
        <translation>Registrar una nota en el paso actual del ensayo</translation>
    </message>
    <message>
        <source>Add note</source>
        <translation>Añadir nota</translation>
    </message>
    <message>
        <source>Load and start a test first.</source>
        <translation>Primero cargue e inicie un ensayo.</translation>
    </message>
    <message>
        <source>Note (recorded with the current step and test time):</source>
        <translation>Nota (se registra con el paso y el tiempo de ensayo actuales):</translation>
    </message>
    <message>
        <source>Quit the console (asks first while a test runs)</source>
        <translation>Salir de la consola (pregunta antes si hay un ensayo en curso)</translation>
    </message>
    <message>
        <source>testing the link...</source>
        <translation>probando el enlace...</translation>
    </message>
    <message>
        <source>This ground motion cannot be used: %1</source>
        <translation>Este movimiento del suelo no se puede usar: %1</translation>
    </message>
    <message>
        <source>ground motion not usable: %1</source>
        <translation>movimiento del suelo no utilizable: %1</translation>
    </message>
    <message>
        <source>A test is running</source>
        <translation>Hay un ensayo en curso</translation>
    </message>
    <message>
        <source>Continue the test</source>
        <translation>Continuar el ensayo</translation>
    </message>
    <message>
        <source>End the test now? The specimen is held, the test cannot be resumed, and every step so far stays in the record.</source>
        <translation>¿Terminar el ensayo ahora? La probeta queda retenida, el ensayo no se puede reanudar y todos los pasos hasta ahora quedan en el registro.</translation>
    </message>
    <message>
        <source>End the test and keep the data</source>
        <translation>Terminar el ensayo y conservar los datos</translation>
    </message>
    <message>
        <source>link tested: %1 answered; the test is prepared, Start shows the pre-flight check</source>
        <translation>enlace probado: %1 respondió; el ensayo está preparado, Iniciar muestra la comprobación previa</translation>
    </message>
    <message>
        <source>A test is running. Quit the console? The test is ended first: the specimen is held and every step so far stays in the record.</source>
        <translation>Hay un ensayo en curso. ¿Salir de la consola? Primero se termina el ensayo: la probeta queda retenida y todos los pasos hasta ahora quedan en el registro.</translation>
    </message>
    <message>
        <source>End the test, keep the data and quit</source>
        <translation>Terminar el ensayo, conservar los datos y salir</translation>
    </message>
    <message>
        <source>(dataSize %1; ctrl sizes %2; daq sizes %3)</source>
        <translation>(dataSize %1; tamaños ctrl %2; tamaños daq %3)</translation>
    </message>
    <message>
        <source>test finished: %1 steps, t = %2 s</source>
        <translation>ensayo terminado: %1 pasos, t = %2 s</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <source>Console &amp;guide</source>
        <translation>&amp;Guía de la consola</translation>
    </message>
    <message>
        <source>The console&apos;s documentation (docs/console.md)</source>
        <translation>La documentación de la consola (docs/console.md)</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>Atajos de &amp;teclado</translation>
    </message>
    <message>
        <source>&amp;About HSMU Console</source>
        <translation>&amp;Acerca de HSMU Console</translation>
    </message>
    <message>
        <source>%1: Start (after the pre-flight check)</source>
        <translation>%1: Iniciar (tras la verificación previa)</translation>
    </message>
    <message>
        <source>%1: Pause</source>
        <translation>%1: Pausar</translation>
    </message>
    <message>
        <source>%1: Resume</source>
        <translation>%1: Reanudar</translation>
    </message>
    <message>
        <source>%1: Single step</source>
        <translation>%1: Un paso</translation>
    </message>
    <message>
        <source>%1: Stop (asks first)</source>
        <translation>%1: Detener (pregunta antes)</translation>
    </message>
    <message>
        <source>%1: Emergency hold (every window, always)</source>
        <translation>%1: Retención de emergencia (en toda ventana, siempre)</translation>
    </message>
    <message>
        <source>%1: Add a note to the record</source>
        <translation>%1: Añadir una nota al registro</translation>
    </message>
    <message>
        <source>%1: Open a configuration</source>
        <translation>%1: Abrir una configuración</translation>
    </message>
    <message>
        <source>%1: Copy the selected alarms and events</source>
        <translation>%1: Copiar las alarmas y eventos seleccionados</translation>
    </message>
    <message>
        <source>%1: Console guide</source>
        <translation>%1: Guía de la consola</translation>
    </message>
    <message>
        <source>%1: Quit (asks first while a test runs)</source>
        <translation>%1: Salir (pregunta antes si hay un ensayo en curso)</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Atajos de teclado</translation>
    </message>
    <message>
        <source>About HSMU Console</source>
        <translation>Acerca de HSMU Console</translation>
    </message>
    <message>
        <source>HSMU Console %1
Hybrid simulation with online model updating (Hashemi, Masroor &amp; Mosqueda, EESD 2014).</source>
        <translation>HSMU Console %1
Simulación híbrida con actualización del modelo en línea (Hashemi, Masroor y Mosqueda, EESD 2014).</translation>
    </message>
    <message>
        <source>Console guide</source>
        <translation>Guía de la consola</translation>
    </message>
    <message>
        <source>The guide is docs/console.md of the source tree, installed as share/doc/hsmu/console.md.</source>
        <translation>La guía es docs/console.md del árbol de fuentes, instalada como share/doc/hsmu/console.md.</translation>
    </message>
    <message>
        <source>asking the controller for a fresh specimen...</source>
        <translation>solicitando al controlador una probeta nueva...</translation>
    </message>
    <message>
        <source>Real-time hybrid simulation</source>
        <translation>Simulación híbrida en tiempo real</translation>
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
        <translation>Doble clic para editar; efectivo en el siguiente paso</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parámetro</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Sigma</source>
        <translation>Sigma</translation>
    </message>
    <message>
        <source>Lower</source>
        <translation>Inferior</translation>
    </message>
    <message>
        <source>Upper</source>
        <translation>Superior</translation>
    </message>
    <message>
        <source>Lock</source>
        <translation>Bloquear</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: &apos;%2&apos; no es un número</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ParametersPanel</name>
    <message>
        <source>No online model updating in this test.</source>
        <translation>Este ensayo no tiene actualización del modelo en línea.</translation>
    </message>
    <message>
        <source>Normalized RMS fit error above which the inspector requests an update; effective on the next step</source>
        <translation>Error de ajuste RMS normalizado por encima del cual el inspector solicita una actualización; efectivo en el siguiente paso</translation>
    </message>
    <message>
        <source>Fit-error threshold [-]:</source>
        <translation>Umbral del error de ajuste [-]:</translation>
    </message>
    <message>
        <source>Value, sigma (1 standard deviation) and bounds in the law&apos;s normalized units (u / u_ref, F / F_ref). Double-click a bound to edit it; bound and lock edits take effect on the next step.</source>
        <translation>Valor, sigma (1 desviación estándar) y límites en las unidades normalizadas de la ley (u / u_ref, F / F_ref). Haga doble clic en un límite para editarlo; los cambios de límites y bloqueos surten efecto en el siguiente paso.</translation>
    </message>
    <message>
        <source>%1 on %2 at step %3: fit error e = %4 (threshold %5), %6 updates applied</source>
        <translation>%1 en %2 en el paso %3: error de ajuste e = %4 (umbral %5), %6 actualizaciones aplicadas</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PendingUpdatesPanel</name>
    <message>
        <source>every step</source>
        <translation>en cada paso</translation>
    </message>
    <message>
        <source>at zero-force crossings of the target</source>
        <translation>en los cruces por fuerza cero del objetivo</translation>
    </message>
    <message>
        <source>every N steps</source>
        <translation>cada N pasos</translation>
    </message>
    <message>
        <source>on the operator&apos;s approval</source>
        <translation>con la aprobación del operador</translation>
    </message>
    <message>
        <source>N = </source>
        <translation>N = </translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parámetro</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Actual</translation>
    </message>
    <message>
        <source>Proposed</source>
        <translation>Propuesto</translation>
    </message>
    <message>
        <source>Change [%]</source>
        <translation>Cambio [%]</translation>
    </message>
    <message>
        <source>Apply updates:</source>
        <translation>Aplicar actualizaciones:</translation>
    </message>
    <message>
        <source>No online model updating in this test.</source>
        <translation>Este ensayo no tiene actualización del modelo en línea.</translation>
    </message>
    <message>
        <source>Updates are applied %1; choose &quot;on the operator&apos;s approval&quot; to decide each one.</source>
        <translation>Las actualizaciones se aplican %1; elija &quot;con la aprobación del operador&quot; para decidir cada una.</translation>
    </message>
    <message>
        <source>#%1 %2 at t = %3 s (step %4)</source>
        <translation>#%1 %2 en t = %3 s (paso %4)</translation>
    </message>
    <message>
        <source>Approve</source>
        <translation>Aprobar</translation>
    </message>
    <message>
        <source>Reject</source>
        <translation>Rechazar</translation>
    </message>
    <message numerus="yes">
        <source>%n newer proposal(s) were not queued (the queue holds %1); each is in the record.</source>
        <translation>
            <numerusform>%n propuesta más reciente no se encoló (la cola admite %1); cada una está en el registro.</numerusform>
            <numerusform>%n propuestas más recientes no se encolaron (la cola admite %1); cada una está en el registro.</numerusform>
        </translation>
    </message>
    <message>
        <source>, fit error %1</source>
        <translation>, error de ajuste %1</translation>
    </message>
    <message>
        <source>Estimate now</source>
        <translation>Estim. actual</translation>
    </message>
    <message>
        <source>The target&apos;s current value, the proposed one, the estimator&apos;s value now and the change the proposal makes, in the law&apos;s normalized units</source>
        <translation>El valor actual del objetivo, el propuesto, el valor actual del estimador y el cambio que hace la propuesta, en las unidades normalizadas de la ley</translation>
    </message>
    <message numerus="yes">
        <source>%n update(s) waiting for a decision.</source>
        <translation>
            <numerusform>%n actualización espera una decisión.</numerusform>
            <numerusform>%n actualizaciones esperan una decisión.</numerusform>
        </translation>
    </message>
    <message>
        <source>One proposal per target, renewed every %1 s of test time with the estimator&apos;s latest values (it replaces the one shown); Approve applies the values shown while they are current.</source>
        <translation>Una propuesta por objetivo, renovada cada %1 s de tiempo de ensayo con los últimos valores del estimador (sustituye a la mostrada); Aprobar aplica los valores mostrados mientras estén vigentes.</translation>
    </message>
    <message>
        <source>: stale (older than %1 s), wait for the next proposal</source>
        <translation>: caducada (más de %1 s), espere la siguiente propuesta</translation>
    </message>
    <message>
        <source>Approve offsets</source>
        <translation>Aprobar desplazamientos de cero</translation>
    </message>
    <message>
        <source>Reject offsets</source>
        <translation>Rechazar desplazamientos de cero</translation>
    </message>
    <message>
        <source>%1%2 (on its bound, no interval)</source>
        <translation>%1%2 (en su límite, sin intervalo)</translation>
    </message>
    <message>
        <source>%1 +- %2%3 (95 %)</source>
        <translation>%1 +- %2%3 (95 %)</translation>
    </message>
    <message>
        <source>Offsets #%1 for the twins: u0 = %2, F0 = %3</source>
        <translation>Desplazamientos de cero #%1 para los gemelos: u0 = %2, F0 = %3</translation>
    </message>
    <message>
        <source>Found at t = %1 s (step %2) on %3 samples; the specimen&apos;s NRMSE %4 without them, %5 with them. They reach the twins (F = F_law(u - u0) + F0) only if you approve them, whatever the policy.</source>
        <translation>Hallados en t = %1 s (paso %2) sobre %3 muestras; NRMSE del espécimen %4 sin ellos, %5 con ellos. Llegan a los gemelos (F = F_ley(u - u0) + F0) solo si usted los aprueba, sea cual sea la política.</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PlotElementPicker</name>
    <message>
        <source>Element:</source>
        <translation>Elemento:</translation>
    </message>
    <message>
        <source>The element this plot shows</source>
        <translation>El elemento que muestra este gráfico</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PlotTools</name>
    <message>
        <source>x = %1, y = %2</source>
        <translation>x = %1, y = %2</translation>
    </message>
    <message>
        <source>%1: %2 at %3</source>
        <translation>%1: %2 en %3</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: no se puede escribir (%2)</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>Escala automática</translation>
    </message>
    <message>
        <source>Channels</source>
        <translation>Canales</translation>
    </message>
    <message>
        <source>curve %1</source>
        <translation>curva %1</translation>
    </message>
    <message>
        <source>Export visible data as CSV...</source>
        <translation>Exportar los datos visibles como CSV...</translation>
    </message>
    <message>
        <source>Export visible data</source>
        <translation>Exportar los datos visibles</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PreflightDialog</name>
    <message>
        <source>Pre-flight check</source>
        <translation>Comprobación previa</translation>
    </message>
    <message>
        <source>Integration and stability</source>
        <translation>Integración y estabilidad</translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation>Integrador:</translation>
    </message>
    <message>
        <source>Time step dt [s]:</source>
        <translation>Paso de tiempo dt [s]:</translation>
    </message>
    <message>
        <source>Steps:</source>
        <translation>Pasos:</translation>
    </message>
    <message>
        <source>Ground motion:</source>
        <translation>Movimiento del suelo:</translation>
    </message>
    <message>
        <source>%1, PGA %2 m/s²</source>
        <translation>%1, PGA %2 m/s²</translation>
    </message>
    <message>
        <source>omega_max [rad/s]:</source>
        <translation>omega_max [rad/s]:</translation>
    </message>
    <message>
        <source>omega_max dt [-] / limit:</source>
        <translation>omega_max dt [-] / límite:</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>unconditionally stable</source>
        <translation>incondicionalmente estable</translation>
    </message>
    <message>
        <source>Stable: %1</source>
        <translation>Estable: %1</translation>
    </message>
    <message>
        <source>UNSTABLE: %1%2</source>
        <translation>INESTABLE: %1%2</translation>
    </message>
    <message>
        <source> (forced by the configuration)</source>
        <translation> (forzado por la configuración)</translation>
    </message>
    <message>
        <source>Check:</source>
        <translation>Verificación:</translation>
    </message>
    <message>
        <source>Specimens: limits and initial measured values</source>
        <translation>Probetas: límites y valores medidos iniciales</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Max |d|</source>
        <translation>Máx. |d|</translation>
    </message>
    <message>
        <source>Max |F|</source>
        <translation>Máx. |F|</translation>
    </message>
    <message>
        <source>Max |Δd| per step</source>
        <translation>Máx. |Δd| por paso</translation>
    </message>
    <message>
        <source>Measured d</source>
        <translation>d medido</translation>
    </message>
    <message>
        <source>Measured F</source>
        <translation>F medida</translation>
    </message>
    <message>
        <source>Measured d and F: what the specimen reported after the link was prepared, before any target was sent.</source>
        <translation>d y F medidos: lo que la probeta informó tras preparar el enlace, antes de enviar ningún objetivo.</translation>
    </message>
    <message>
        <source>I confirm the zero offsets: with the specimen unloaded the actuator displacement and the load cell read zero.</source>
        <translation>Confirmo el ajuste de cero: con la probeta descargada, el desplazamiento del actuador y la célula de carga marcan cero.</translation>
    </message>
    <message>
        <source>Start test</source>
        <translation>Iniciar ensayo</translation>
    </message>
    <message>
        <source>Please check:</source>
        <translation>Revise:</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>explicit Newmark</source>
        <translation>Newmark explícito</translation>
    </message>
    <message>
        <source>alpha-OS</source>
        <translation>alpha-OS</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>sin medir</translation>
    </message>
    <message>
        <source>Measured d and F: what the specimen reported after the link was prepared, before any target was sent; for a specimen loaded by an earlier test, d is its last committed deformation and F is measured at the first step.</source>
        <translation>d y F medidos: lo que la probeta informó tras preparar el enlace, antes de enviar ningún objetivo; para una probeta cargada por un ensayo anterior, d es su última deformación confirmada y F se mide en el primer paso.</translation>
    </message>
    <message>
        <source>Specimen loaded by an earlier test</source>
        <translation>Probeta cargada por un ensayo anterior</translation>
    </message>
    <message>
        <source>%1 has %L2 committed steps from an earlier test; its last committed deformation is %3 %4. This test starts from rest: its first target moves the specimen from there.</source>
        <translation>%1 tiene %L2 pasos confirmados de un ensayo anterior; su última deformación confirmada es %3 %4. Este ensayo parte del reposo: su primer objetivo mueve la probeta desde allí.</translation>
    </message>
    <message>
        <source>Its controller refused a fresh specimen (%1): replace the specimen at the controller and restart the controller without its state file, or continue on the loaded specimen.</source>
        <translation>Su controlador rechazó una probeta nueva (%1): sustituya la probeta en el controlador y reinicie el controlador sin su archivo de estado, o continúe con la probeta cargada.</translation>
    </message>
    <message>
        <source>Choose: continue on the loaded specimen (its damage is part of this test), or a fresh specimen (its controller resets it to step 0, then this check is shown again).</source>
        <translation>Elija: continuar con la probeta cargada (su daño forma parte de este ensayo) o una probeta nueva (su controlador la reinicia al paso 0 y luego se muestra de nuevo esta verificación).</translation>
    </message>
    <message>
        <source>Continue on the loaded specimen</source>
        <translation>Continuar con la probeta cargada</translation>
    </message>
    <message>
        <source>Fresh specimen</source>
        <translation>Probeta nueva</translation>
    </message>
    <message>
        <source>Reset the specimen</source>
        <translation>Reiniciar la probeta</translation>
    </message>
    <message>
        <source>Continuing would move it by about %1 %2 at the first step, more than the increment limit %3 %2: the controller would hold the test. Choose a fresh specimen, or bring the specimen back to rest at the controller.</source>
        <translation>Continuar la movería unos %1 %2 en el primer paso, más que el límite de incremento %3 %2: el controlador retendría el ensayo. Elija una probeta nueva o lleve la probeta al reposo en el controlador.</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReidentifyDialog</name>
    <message>
        <source>Re-identify</source>
        <translation>Reidentificar</translation>
    </message>
    <message>
        <source>UKF</source>
        <translation>UKF</translation>
    </message>
    <message>
        <source>Nelder-Mead</source>
        <translation>Nelder-Mead</translation>
    </message>
    <message>
        <source>none: the recorded settings</source>
        <translation>ninguno: la configuración registrada</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Examinar...</translation>
    </message>
    <message>
        <source>Override settings</source>
        <translation>Configuración que sustituye</translation>
    </message>
    <message>
        <source>JSON (*.json);;All files (*)</source>
        <translation>JSON (*.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>Método</translation>
    </message>
    <message>
        <source>Override (JSON)</source>
        <translation>Sustitución (JSON)</translation>
    </message>
    <message>
        <source>{&quot;model&quot;: ..., &quot;updating&quot;: ...} merged into the recorded settings, as hsmu replay --config</source>
        <translation>{&quot;model&quot;: ..., &quot;updating&quot;: ...} combinado con la configuración registrada, como hsmu replay --config</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>Aceptar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReplayEventList</name>
    <message>
        <source>Time [s]</source>
        <translation>Tiempo [s]</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Paso</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Event, alarm or note</source>
        <translation>Evento, alarma o nota</translation>
    </message>
    <message>
        <source>operator</source>
        <translation>operador</translation>
    </message>
    <message>
        <source>note</source>
        <translation>nota</translation>
    </message>
    <message>
        <source>Double-click (or Enter) to jump to the step</source>
        <translation>Doble clic (o Intro) para ir al paso</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReplayReadout</name>
    <message>
        <source>Quantity</source>
        <translation>Magnitud</translation>
    </message>
    <message>
        <source>Value at the cursor</source>
        <translation>Valor en el cursor</translation>
    </message>
    <message>
        <source>step</source>
        <translation>paso</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>ag [m/s²]</source>
        <translation>ag [m/s²]</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReplayWindow</name>
    <message>
        <source>Open record</source>
        <translation>Abrir registro</translation>
    </message>
    <message>
        <source>HSMU records (*.h5 *.hdf5);;All files (*)</source>
        <translation>Registros HSMU (*.h5 *.hdf5);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Cannot open the record</source>
        <translation>No se puede abrir el registro</translation>
    </message>
    <message>
        <source>HSMU Replay - %1 (%2)</source>
        <translation>Reproducción HSMU - %1 (%2)</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Reproducción</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
    <message>
        <source> Speed </source>
        <translation> Velocidad </translation>
    </message>
    <message>
        <source>%1 x</source>
        <translation>%1 x</translation>
    </message>
    <message>
        <source>Test seconds per wall second</source>
        <translation>Segundos de ensayo por segundo real</translation>
    </message>
    <message>
        <source>Scrub through the record</source>
        <translation>Desplazarse por el registro</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausar</translation>
    </message>
    <message>
        <source> t = %1 s   step %2 of %3 </source>
        <translation> t = %1 s   paso %2 de %3 </translation>
    </message>
    <message>
        <source>Re-identify...</source>
        <translation>Reidentificar...</translation>
    </message>
    <message>
        <source>Identify the specimen again with other settings and overlay the parameter history</source>
        <translation>Identificar de nuevo el espécimen con otra configuración y superponer la historia de parámetros</translation>
    </message>
    <message>
        <source>identifying</source>
        <translation>identificando</translation>
    </message>
    <message>
        <source>Re-identifying the specimen</source>
        <translation>Reidentificando el espécimen</translation>
    </message>
    <message>
        <source>re-identified (%1)</source>
        <translation>reidentificado (%1)</translation>
    </message>
    <message>
        <source>Re-identification failed</source>
        <translation>La reidentificación falló</translation>
    </message>
    <message>
        <source>Events, alarms and notes</source>
        <translation>Eventos, alarmas y notas</translation>
    </message>
    <message>
        <source>Values at the cursor</source>
        <translation>Valores en el cursor</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>Export time window as &amp;CSV...</source>
        <translation>Exportar la ventana de tiempo como &amp;CSV...</translation>
    </message>
    <message>
        <source>Export time window</source>
        <translation>Exportar la ventana de tiempo</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export &amp;plots (PNG, SVG or PDF)...</source>
        <translation>Exportar &amp;gráficos (PNG, SVG o PDF)...</translation>
    </message>
    <message>
        <source>Export plots</source>
        <translation>Exportar gráficos</translation>
    </message>
    <message>
        <source>PNG images (*.png);;SVG drawings (*.svg);;PDF documents (*.pdf)</source>
        <translation>Imágenes PNG (*.png);;Dibujos SVG (*.svg);;Documentos PDF (*.pdf)</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Cerrar</translation>
    </message>
    <message>
        <source>&amp;Playback</source>
        <translation>&amp;Reproducción</translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation>Paso &amp;atrás</translation>
    </message>
    <message>
        <source>Step &amp;forward</source>
        <translation>Paso a&amp;delante</translation>
    </message>
    <message>
        <source>To the &amp;start</source>
        <translation>Al &amp;inicio</translation>
    </message>
    <message>
        <source>To the &amp;end</source>
        <translation>Al &amp;final</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::RthsPanel</name>
    <message>
        <source>RTHS proposal #%1 rejected</source>
        <translation>Propuesta RTHS n.º %1 rechazada</translation>
    </message>
    <message>
        <source>RTHS proposal #%1 approved</source>
        <translation>Propuesta RTHS n.º %1 aprobada</translation>
    </message>
    <message>
        <source>Damper twin</source>
        <translation>Gemelo del amortiguador</translation>
    </message>
    <message>
        <source>Tracking</source>
        <translation>Seguimiento</translation>
    </message>
    <message>
        <source>Go on with the held run from the tick where it held (refused while a limit is still breached)</source>
        <translation>Continuar el ensayo detenido desde el ciclo en que se detuvo (se rechaza mientras un límite siga superado)</translation>
    </message>
    <message>
        <source>Not resumed: %1</source>
        <translation>No reanudado: %1</translation>
    </message>
    <message>
        <source>RTHS run not resumed: %1</source>
        <translation>Ensayo RTHS no reanudado: %1</translation>
    </message>
    <message>
        <source>RTHS resume</source>
        <translation>Reanudación RTHS</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Reanudar</translation>
    </message>
    <message>
        <source>Resumed</source>
        <translation>Reanudado</translation>
    </message>
    <message>
        <source>No RTHS run yet.</source>
        <translation>Aún no hay ningún ensayo RTHS.</translation>
    </message>
    <message>
        <source>Run:</source>
        <translation>Ensayo:</translation>
    </message>
    <message>
        <source>Benchmark case %1</source>
        <translation>Caso de referencia %1</translation>
    </message>
    <message>
        <source>Configuration file</source>
        <translation>Archivo de configuración</translation>
    </message>
    <message>
        <source>RTHS configuration (.json)</source>
        <translation>configuración RTHS (.json)</translation>
    </message>
    <message>
        <source>Choose an RTHS configuration file</source>
        <translation>Elegir un archivo de configuración RTHS</translation>
    </message>
    <message>
        <source>Pace:</source>
        <translation>Ritmo:</translation>
    </message>
    <message>
        <source>Fast (simulated)</source>
        <translation>Rápido (simulado)</translation>
    </message>
    <message>
        <source>Real time</source>
        <translation>Tiempo real</translation>
    </message>
    <message>
        <source>Duration:</source>
        <translation>Duración:</translation>
    </message>
    <message>
        <source>whole record</source>
        <translation>registro completo</translation>
    </message>
    <message>
        <source>Stop the run after this many seconds of test time (0: the whole record)</source>
        <translation>Detener el ensayo tras estos segundos de tiempo de ensayo (0: el registro completo)</translation>
    </message>
    <message>
        <source>Start RTHS</source>
        <translation>Iniciar RTHS</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Detener</translation>
    </message>
    <message>
        <source>Hold the loop before its next tick (Resume goes on from there)</source>
        <translation>Detener el lazo antes de su siguiente ciclo (Reanudar continúa desde ahí)</translation>
    </message>
    <message>
        <source>Emergency hold</source>
        <translation>Retención de emergencia</translation>
    </message>
    <message>
        <source>Live tracking</source>
        <translation>Seguimiento en vivo</translation>
    </message>
    <message>
        <source>Warning above</source>
        <translation>Aviso por encima de</translation>
    </message>
    <message>
        <source>Critical above</source>
        <translation>Crítico por encima de</translation>
    </message>
    <message>
        <source>J1 delay</source>
        <translation>J1 retardo</translation>
    </message>
    <message>
        <source>J2 tracking error</source>
        <translation>J2 error de seguimiento</translation>
    </message>
    <message>
        <source>RTHS configuration</source>
        <translation>Configuración RTHS</translation>
    </message>
    <message>
        <source>Configuration (*.json)</source>
        <translation>Configuración (*.json)</translation>
    </message>
    <message>
        <source>choose an RTHS configuration file</source>
        <translation>elija un archivo de configuración RTHS</translation>
    </message>
    <message>
        <source>Cannot start the RTHS run: %1</source>
        <translation>No se puede iniciar el ensayo RTHS: %1</translation>
    </message>
    <message>
        <source>RTHS run &apos;%1&apos; started</source>
        <translation>ensayo RTHS &apos;%1&apos; iniciado</translation>
    </message>
    <message>
        <source>RTHS hold</source>
        <translation>detención RTHS</translation>
    </message>
    <message>
        <source>RTHS emergency hold</source>
        <translation>retención de emergencia RTHS</translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation>No aplicado: %1</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>-- ms</source>
        <translation>-- ms</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>-- %</source>
        <translation>-- %</translation>
    </message>
    <message>
        <source>Amplitude error: %1 %</source>
        <translation>Error de amplitud: %1 %</translation>
    </message>
    <message>
        <source>Amplitude error: -- %</source>
        <translation>Error de amplitud: -- %</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>Finished: %1 ticks (%2 s); whole run J1 %3 ms, J2 %4 %</source>
        <translation>Terminado: %1 ciclos (%2 s); ensayo completo J1 %3 ms, J2 %4 %</translation>
    </message>
    <message>
        <source>RTHS run finished: %1 ticks</source>
        <translation>ensayo RTHS terminado: %1 ciclos</translation>
    </message>
    <message>
        <source>Held after %1 ticks: %2</source>
        <translation>Detenido tras %1 ciclos: %2</translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation>Controlador:</translation>
    </message>
    <message>
        <source>built-in virtual lab, or tcp://HOST:PORT of hsmu-controller --rths</source>
        <translation>laboratorio virtual integrado, o tcp://HOST:PUERTO de hsmu-controller --rths</translation>
    </message>
    <message>
        <source>Empty: the loop runs in the console. tcp://HOST:PORT: monitor the loop hsmu-controller --rths runs (its token from HSMU_CONTROLLER_TOKEN)</source>
        <translation>Vacío: el lazo se ejecuta en la consola. tcp://HOST:PUERTO: supervisar el lazo que ejecuta hsmu-controller --rths (su token de HSMU_CONTROLLER_TOKEN)</translation>
    </message>
    <message>
        <source>controller: an RTHS loop is monitored over tcp://HOST:PORT (hsmu-controller --rths)</source>
        <translation>controlador: un lazo RTHS se supervisa por tcp://HOST:PUERTO (hsmu-controller --rths)</translation>
    </message>
    <message>
        <source>real time; pre-flight: %1</source>
        <translation>tiempo real; comprobación previa: %1</translation>
    </message>
    <message>
        <source>fast; pre-flight: %1</source>
        <translation>rápido; comprobación previa: %1</translation>
    </message>
    <message>
        <source>on the controller %1:%2</source>
        <translation>en el controlador %1:%2</translation>
    </message>
    <message>
        <source>Running &apos;%1&apos; at %2 Hz (%3)</source>
        <translation>Ejecutando &apos;%1&apos; a %2 Hz (%3)</translation>
    </message>
    <message>
        <source>The RTHS run could not be followed: %1</source>
        <translation>No se pudo seguir el ensayo RTHS: %1</translation>
    </message>
    <message>
        <source>Record folder:</source>
        <translation>Carpeta del registro:</translation>
    </message>
    <message>
        <source>not recorded</source>
        <translation>sin registro</translation>
    </message>
    <message>
        <source>Every tick of a run from this view goes to record.h5 in this folder (record-2.h5, record-3.h5, ... when taken: nothing is overwritten); empty: not recorded</source>
        <translation>Cada tic de un ensayo iniciado desde esta vista se escribe en record.h5 en esta carpeta (record-2.h5, record-3.h5, ... si ya existe: nada se sobrescribe); vacía: sin registro</translation>
    </message>
    <message>
        <source>Recorded on the controller, not by the console: %1</source>
        <translation>Lo registra el controlador, no la consola: %1</translation>
    </message>
    <message>
        <source>Not recorded (no record folder)</source>
        <translation>Sin registro (no hay carpeta del registro)</translation>
    </message>
    <message>
        <source>Recording every tick to %1</source>
        <translation>Registrando cada tic en %1</translation>
    </message>
    <message>
        <source>Recorded on the controller, not by the console (waiting for the controller&apos;s description)</source>
        <translation>Lo registra el controlador, no la consola (esperando la descripción del controlador)</translation>
    </message>
    <message>
        <source>The record %1 is incomplete: %2</source>
        <translation>El registro %1 está incompleto: %2</translation>
    </message>
    <message>
        <source>Recorded %1 ticks to %2</source>
        <translation>%1 tics registrados en %2</translation>
    </message>
    <message>
        <source>No estimate: the command&apos;s RMS %1 mm is below %2 mm</source>
        <translation>Sin estimación: el RMS de la consigna, %1 mm, está por debajo de %2 mm</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::RthsSession</name>
    <message>
        <source>no controller&apos;s RTHS run is going</source>
        <translation>no hay ningún ensayo RTHS de un controlador en curso</translation>
    </message>
    <message>
        <source>this RTHS run has no damper twin</source>
        <translation>este ensayo RTHS no tiene gemelo del amortiguador</translation>
    </message>
    <message>
        <source>the link to the controller is closed</source>
        <translation>el enlace con el controlador está cerrado</translation>
    </message>
    <message>
        <source>no RTHS run is going</source>
        <translation>no hay ningún ensayo RTHS en curso</translation>
    </message>
    <message>
        <source>no held RTHS run to resume</source>
        <translation>no hay ningún ensayo RTHS detenido que reanudar</translation>
    </message>
    <message>
        <source>an RTHS run is already going</source>
        <translation>ya hay un ensayo RTHS en curso</translation>
    </message>
    <message>
        <source>refused in pre-flight: %1</source>
        <translation>rechazado en la comprobación previa: %1</translation>
    </message>
    <message>
        <source>the controller&apos;s (%1:%2)</source>
        <translation>la del controlador (%1:%2)</translation>
    </message>
    <message>
        <source>the link to the controller was lost: %1 (the controller holds the loop per its --monitor-loss policy)</source>
        <translation>se perdió el enlace con el controlador: %1 (el controlador detiene el lazo según su política --monitor-loss)</translation>
    </message>
    <message>
        <source>the record cannot be created in %1: %2</source>
        <translation>no se puede crear el registro en %1: %2</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SettingsDialog</name>
    <message>
        <source>Settings</source>
        <translation>Preferencias</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Predeterminado del sistema</translation>
    </message>
    <message>
        <source>Clear recent files</source>
        <translation>Borrar archivos recientes</translation>
    </message>
    <message>
        <source>empty: tests are not recorded</source>
        <translation>vacío: los ensayos no se registran</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Examinar...</translation>
    </message>
    <message>
        <source>Record folder</source>
        <translation>Carpeta de registros</translation>
    </message>
    <message>
        <source>Record folder (HDF5):</source>
        <translation>Carpeta de registros (HDF5):</translation>
    </message>
    <message>
        <source>Language:</source>
        <translation>Idioma:</translation>
    </message>
    <message>
        <source>Recent files:</source>
        <translation>Archivos recientes:</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>Aceptar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>A new language applies at once, to every window.</source>
        <translation>Un idioma nuevo se aplica de inmediato, a todas las ventanas.</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SetupPanel</name>
    <message>
        <source>Record&apos;s sample step [s]:</source>
        <translation>Paso de muestreo del registro [s]:</translation>
    </message>
    <message>
        <source>The time between the record&apos;s samples. A file of acceleration values only (one column) needs it; an AT2 header or a time column gives its own. Not the integration step dt.</source>
        <translation>El tiempo entre las muestras del registro. Un archivo solo de valores de aceleración (una columna) lo necesita; una cabecera AT2 o una columna de tiempo dan el suyo. No es el paso de integración dt.</translation>
    </message>
    <message>
        <source>from the file</source>
        <translation>del archivo</translation>
    </message>
    <message>
        <source>No configuration loaded: choose a preset or open a file.</source>
        <translation>Ninguna configuración cargada: elija un preajuste o abra un archivo.</translation>
    </message>
    <message>
        <source>Safety limits (0 = none; the specimen&apos;s units)</source>
        <translation>Límites de seguridad (0 = ninguno; unidades de la probeta)</translation>
    </message>
    <message>
        <source>Specimen</source>
        <translation>Probeta</translation>
    </message>
    <message>
        <source>Max |d|</source>
        <translation>Máx. |d|</translation>
    </message>
    <message>
        <source>Max |F|</source>
        <translation>Máx. |F|</translation>
    </message>
    <message>
        <source>Max |Δd| per step</source>
        <translation>Máx. |Δd| por paso</translation>
    </message>
    <message>
        <source>Apply (reload the test)</source>
        <translation>Aplicar (recargar el ensayo)</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Ensayo</translation>
    </message>
    <message>
        <source>the configuration&apos;s record</source>
        <translation>el registro de la configuración</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Examinar...</translation>
    </message>
    <message>
        <source>Ground motion file:</source>
        <translation>Archivo de movimiento del suelo:</translation>
    </message>
    <message>
        <source>Scale [-]:</source>
        <translation>Escala [-]:</translation>
    </message>
    <message>
        <source>Time step dt [s]:</source>
        <translation>Paso de tiempo dt [s]:</translation>
    </message>
    <message>
        <source>whole record</source>
        <translation>registro completo</translation>
    </message>
    <message>
        <source>Duration [s]:</source>
        <translation>Duración [s]:</translation>
    </message>
    <message>
        <source>explicit Newmark</source>
        <translation>Newmark explícito</translation>
    </message>
    <message>
        <source>alpha-OS</source>
        <translation>alpha-OS</translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation>Integrador:</translation>
    </message>
    <message>
        <source>alpha-OS alpha [-]:</source>
        <translation>alpha de alpha-OS [-]:</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Controlador</translation>
    </message>
    <message>
        <source>built-in virtual lab</source>
        <translation>laboratorio virtual integrado</translation>
    </message>
    <message>
        <source>hsmu-controller over TCP</source>
        <translation>hsmu-controller por TCP</translation>
    </message>
    <message>
        <source>Specimens driven by:</source>
        <translation>Probetas accionadas por:</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>Host:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Puerto:</translation>
    </message>
    <message>
        <source>Online model updating</source>
        <translation>Actualización del modelo en línea</translation>
    </message>
    <message>
        <source>enabled</source>
        <translation>habilitada</translation>
    </message>
    <message>
        <source>Fit-error threshold [-]:</source>
        <translation>Umbral del error de ajuste [-]:</translation>
    </message>
    <message>
        <source>Ground motion record</source>
        <translation>Registro de movimiento del suelo</translation>
    </message>
    <message>
        <source>Ground motions (*.AT2 *.at2 *.txt *.csv *.dat);;All files (*)</source>
        <translation>Movimientos del suelo (*.AT2 *.at2 *.txt *.csv *.dat);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Configuration: %1
%2</source>
        <translation>Configuración: %1
%2</translation>
    </message>
    <message>
        <source>(built in)</source>
        <translation>(integrada)</translation>
    </message>
    <message>
        <source>built-in %1 record</source>
        <translation>registro %1 integrado</translation>
    </message>
    <message>
        <source>d in %1, F in %2</source>
        <translation>d en %1, F en %2</translation>
    </message>
    <message>
        <source>no configuration loaded</source>
        <translation>ninguna configuración cargada</translation>
    </message>
    <message>
        <source>safety limit of %1: &apos;%2&apos; is not a number &gt;= 0</source>
        <translation>límite de seguridad de %1: &apos;%2&apos; no es un número &gt;= 0</translation>
    </message>
    <message>
        <source>this configuration has no updating section to enable</source>
        <translation>esta configuración no tiene una sección updating que habilitar</translation>
    </message>
    <message>
        <source>OpenFresco SimApp site</source>
        <translation>sitio OpenFresco SimApp</translation>
    </message>
    <message>
        <source>OpenFresco GenericTCP controller</source>
        <translation>controlador OpenFresco GenericTCP</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>The token hsmu-controller --token expects; not saved</source>
        <translation>El token que espera hsmu-controller --token; no se guarda</translation>
    </message>
    <message>
        <source>Token:</source>
        <translation>Token:</translation>
    </message>
    <message>
        <source>Test link</source>
        <translation>Probar enlace</translation>
    </message>
    <message>
        <source>Connect to the controller now (the test is prepared; nothing moves before the pre-flight check)</source>
        <translation>Conectar ahora con el controlador (el ensayo se prepara; nada se mueve antes de la comprobación previa)</translation>
    </message>
    <message>
        <source>When updates are applied is chosen in the Pending updates panel (one setting for the test).</source>
        <translation>Cuándo se aplican las actualizaciones se elige en el panel Actualizaciones pendientes (un solo ajuste para el ensayo).</translation>
    </message>
    <message>
        <source>OpenSees adapter element (numerical substructure)</source>
        <translation>elemento adapter de OpenSees (subestructura numérica)</translation>
    </message>
    <message>
        <source>hsmu-controller over TLS (the configuration&apos;s tls block)</source>
        <translation>hsmu-controller por TLS (el bloque tls de la configuración)</translation>
    </message>
    <message>
        <source>OpenSees listens: start the model with its `element adapter ... PORT` first (its analyze must have at least the test&apos;s steps). A step is final once the next one is sent: after a hold the test cannot repeat it.</source>
        <translation>OpenSees escucha: inicie primero el modelo con su `element adapter ... PORT` (su analyze debe tener al menos los pasos del ensayo). Un paso es definitivo cuando se envía el siguiente: tras una detención el ensayo no puede repetirlo.</translation>
    </message>
    <message>
        <source>synthetic</source>
        <translation>sintético</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SetupSketchView</name>
    <message>
        <source>%1: no 2-D drawing of its setup %2 (a 3-D or aggregated setup); its actuators are in the plot.</source>
        <translation>%1: sin dibujo 2-D de su montaje %2 (un montaje 3-D o agregado); sus actuadores están en el gráfico.</translation>
    </message>
    <message>
        <source>deformed shape x%1 (solid), at rest (dashed)</source>
        <translation>deformada x%1 (continua), en reposo (discontinua)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SiteHealthLabel</name>
    <message>
        <source>down</source>
        <translation>caído</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>last fault: %1</source>
        <translation>último fallo: %1</translation>
    </message>
    <message>
        <source> (faults: %1)</source>
        <translation> (fallos: %1)</translation>
    </message>
    <message>
        <source>connected, %1 ms</source>
        <translation>conectado, %1 ms</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>conectado</translation>
    </message>
    <message>
        <source>link: %1</source>
        <translation>enlace: %1</translation>
    </message>
    <message>
        <source>no link</source>
        <translation>sin enlace</translation>
    </message>
    <message>
        <source>(connects at start)</source>
        <translation>(se conecta al iniciar)</translation>
    </message>
    <message>
        <source>built-in virtual lab</source>
        <translation>laboratorio virtual integrado</translation>
    </message>
    <message>
        <source>%1: built-in virtual lab</source>
        <translation>%1: laboratorio virtual integrado</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SiteHealthView</name>
    <message>
        <source>Sites</source>
        <translation>Sitios</translation>
    </message>
    <message>
        <source>Site</source>
        <translation>Sitio</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Dirección</translation>
    </message>
    <message>
        <source>Specimens</source>
        <translation>Probetas</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>the controller above</source>
        <translation>el controlador de arriba</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SynchronizationPlot</name>
    <message>
        <source>Synchronization: measured against desired</source>
        <translation>Sincronización: medido frente a deseado</translation>
    </message>
    <message>
        <source>desired displacement y [mm]</source>
        <translation>desplazamiento deseado y [mm]</translation>
    </message>
    <message>
        <source>measured displacement xm [mm]</source>
        <translation>desplazamiento medido xm [mm]</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>medido</translation>
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
        <source>not recording</source>
        <translation>sin registrar</translation>
    </message>
    <message>
        <source>recording: %1/%2</source>
        <translation>registrando: %1/%2</translation>
    </message>
    <message>
        <source>%1, %2 left</source>
        <translation>%1, quedan %2</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TestWorker</name>
    <message>
        <source>link restored: the test resumed after an automatic reconnect</source>
        <translation>enlace restablecido: el ensayo se reanudó tras una reconexión automática</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>retención de emergencia por el operador</translation>
    </message>
    <message>
        <source>the record cannot be written: %1</source>
        <translation>no se puede escribir el registro: %1</translation>
    </message>
    <message>
        <source>this test has no model updating</source>
        <translation>este ensayo no tiene actualización del modelo</translation>
    </message>
    <message>
        <source>%1: the lower bound must be a number not above the upper bound</source>
        <translation>%1: el límite inferior debe ser un número no mayor que el límite superior</translation>
    </message>
    <message>
        <source>%1: bounds [%2, %3] refused (they would not keep the law admissible)</source>
        <translation>%1: límites [%2, %3] rechazados (la ley dejaría de ser admisible)</translation>
    </message>
    <message>
        <source>%1: the %2 cannot lock this parameter</source>
        <translation>%1: %2 no puede bloquear este parámetro</translation>
    </message>
    <message>
        <source>update #%1 was not applied (no longer pending, or refused by the law; see the alarms)</source>
        <translation>la actualización #%1 no se aplicó (ya no está pendiente o la ley la rechazó; véanse las alarmas)</translation>
    </message>
    <message>
        <source>update #%1 is no longer pending</source>
        <translation>la actualización #%1 ya no está pendiente</translation>
    </message>
    <message>
        <source>offsets #%1 are no longer pending</source>
        <translation>los desplazamientos de cero #%1 ya no están pendientes</translation>
    </message>
    <message>
        <source>offsets #%1 were not applied: %2</source>
        <translation>los desplazamientos de cero #%1 no se aplicaron: %2</translation>
    </message>
    <message>
        <source>the fit-error threshold must be a positive number</source>
        <translation>el umbral del error de ajuste debe ser un número positivo</translation>
    </message>
    <message>
        <source>the note was not kept: this test is not recorded</source>
        <translation>la nota no se guardó: este ensayo no se registra</translation>
    </message>
    <message>
        <source>link fault (%1): reconnecting in %2 s (attempt %3 of %4)</source>
        <translation>fallo del enlace (%1): reconectando en %2 s (intento %3 de %4)</translation>
    </message>
    <message>
        <source>the note was not kept: %1</source>
        <translation>la nota no se guardó: %1</translation>
    </message>
    <message>
        <source>update #%1 was not applied: the estimate has moved on and #%2 replaced it; check #%2 and approve it if it is right</source>
        <translation>la actualización n.º %1 no se aplicó: la estimación ha cambiado y la n.º %2 la sustituyó; revise la n.º %2 y apruébela si es correcta</translation>
    </message>
    <message>
        <source>update #%1 was not applied: it is older than one proposal interval (%2 s) and no longer what the estimator believes; wait for the next proposal</source>
        <translation>la actualización n.º %1 no se aplicó: es más antigua que un intervalo de propuesta (%2 s) y ya no es lo que cree el estimador; espere la siguiente propuesta</translation>
    </message>
    <message>
        <source>update #%1 is no longer pending: #%2 replaced it</source>
        <translation>la actualización n.º %1 ya no está pendiente: la n.º %2 la sustituyó</translation>
    </message>
    <message>
        <source>the controller of %1 refused a fresh specimen: %2; replace the specimen at the controller, or continue on the loaded specimen</source>
        <translation>el controlador de %1 rechazó una probeta nueva: %2; sustituya la probeta en el controlador o continúe con la probeta cargada</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TrackingHistoryPlot</name>
    <message>
        <source>Delay and amplitude error (moving window)</source>
        <translation>Retardo y error de amplitud (ventana móvil)</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>tiempo [s]</translation>
    </message>
    <message>
        <source>delay [ms]</source>
        <translation>retardo [ms]</translation>
    </message>
    <message>
        <source>amplitude error [%]</source>
        <translation>error de amplitud [%]</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::RthsTwinPanel</name>
    <message>
        <source>Proposal #%1 refused: %2</source>
        <translation>Propuesta n.º %1 rechazada por el lazo: %2</translation>
    </message>
    <message>
        <source>Proposal #%1 applied before tick %2</source>
        <translation>Propuesta n.º %1 aplicada antes del tick %2</translation>
    </message>
    <message>
        <source>Proposal #%1 rejected before tick %2: nothing applied</source>
        <translation>Propuesta n.º %1 rechazada antes del tick %2: no se aplica nada</translation>
    </message>
    <message>
        <source>Proposal #%1 %2</source>
        <translation>Propuesta n.º %1: %2</translation>
    </message>
    <message>
        <source>Proposal #%1 before tick %2: waiting for your approval</source>
        <translation>Propuesta n.º %1 antes del tick %2: pendiente de su aprobación</translation>
    </message>
    <message>
        <source>Reject</source>
        <translation>Rechazar</translation>
    </message>
    <message>
        <source>Apply the selected proposal before the loop&apos;s next tick (refused if outside the bounds)</source>
        <translation>Aplica la propuesta seleccionada antes del siguiente tick del lazo (rechazada si está fuera de los límites)</translation>
    </message>
    <message>
        <source>Approve</source>
        <translation>Aprobar</translation>
    </message>
    <message>
        <source>Proposals waiting for approval (the controller&apos;s identification)</source>
        <translation>Propuestas pendientes de aprobación (la identificación del controlador)</translation>
    </message>
    <message>
        <source>Proposed values</source>
        <translation>Valores propuestos</translation>
    </message>
    <message>
        <source>Fit error</source>
        <translation>Error de ajuste</translation>
    </message>
    <message>
        <source>Tick (time)</source>
        <translation>Tick (tiempo)</translation>
    </message>
    <message>
        <source>Proposal</source>
        <translation>Propuesta</translation>
    </message>
    <message>
        <source>Applied before tick %1 (t = %2 s; %3): %4</source>
        <translation>Aplicado antes del tick %1 (t = %2 s; %3): %4</translation>
    </message>
    <message>
        <source>Refused: %1</source>
        <translation>Rechazado: %1</translation>
    </message>
    <message>
        <source>Refused before tick %1: %2</source>
        <translation>Rechazado antes del tick %1: %2</translation>
    </message>
    <message>
        <source>Sent: applied before the loop&apos;s next tick, or refused with the reason</source>
        <translation>Enviado: se aplica antes del siguiente tick del lazo, o se rechaza con el motivo</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>No enviado: %1</translation>
    </message>
    <message>
        <source>type at least one new value</source>
        <translation>escriba al menos un valor nuevo</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: «%2» no es un número</translation>
    </message>
    <message>
        <source>Damper twin: none in this run</source>
        <translation>Gemelo del amortiguador: ninguno en este ensayo</translation>
    </message>
    <message>
        <source>Damper twin (storey of DOF %1), values in its scales uRef, fRef</source>
        <translation>Gemelo del amortiguador (planta del GDL %1), valores en sus escalas uRef, fRef</translation>
    </message>
    <message>
        <source>Apply the new values to the twin before the loop&apos;s next tick (checked against the bounds first)</source>
        <translation>Aplica los valores nuevos al gemelo antes del siguiente tick del lazo (comprobados antes contra los límites)</translation>
    </message>
    <message>
        <source>Send update</source>
        <translation>Enviar actualización</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>Valor nuevo</translation>
    </message>
    <message>
        <source>Bounds</source>
        <translation>Límites</translation>
    </message>
    <message>
        <source>Physical value</source>
        <translation>Valor físico</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parámetro</translation>
    </message>
</context>
</TS>
