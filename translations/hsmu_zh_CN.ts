<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>CompareCommand</name>
    <message>
        <source>Run the paper&apos;s comparison protocol (reference, initial, updated).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Configuration file or preset name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write PNG plots.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compared numerical element (default: the first updating target).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compared DOF (default: the element&apos;s DOF).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected exactly one CONFIG (a file or a preset name)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 run %2/3: %3 %  (%4 s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the configuration has no online model updating (an enabled &quot;updating&quot; section); compare needs one to run the updated test</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hsmu compare: three runs (reference, initial, updated) of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 steps, %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hsmu compare: the %1 run stopped at step %2 (state %3)%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ComparisonPlotExporter</name>
    <message>
        <source>reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>initial (not updated)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>updated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hysteresis of %1: reference, initial and updated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moment history of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force history of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Displacement of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Displacement [m]</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ComparisonTable</name>
    <message>
        <source>Comparison against the reference run: %1 force [%2], %3 displacement [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>force NRMSE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>force peak error [%1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>displ. NRMSE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>displ. peak error [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>initial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>updated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  initial / updated NRMSE: force %1x, displacement %2x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Final parameters of the updated run (%1 updates applied):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>std</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>true</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ConsoleCommand</name>
    <message>
        <source>HSMU Console: hybrid simulation with online model updating.
Subcommands: run CONFIG --out DIR ..., compare CONFIG --out DIR ..., material --law ... (see hsmu run --help, hsmu compare --help, docs/cli.md).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load a preset or configuration and start it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground-motion record file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test time per wall time (0: as fast as possible).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grab the window into this PNG file, then quit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seconds before the screenshot (default 4).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown subcommand &apos;%1&apos; (expected run, compare or material)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--screenshot-after: expected a number of seconds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--speed: expected a number</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MaterialCommand</name>
    <message>
        <source>Drive one hysteresis law with a deformation history.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Law: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A law parameter (repeatable).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deformation history (CSV or text).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output CSV (default: stdout).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing --law (one of %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing --history FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--param &apos;%1&apos;: expected NAME=VALUE with a finite number</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>OverrideOptions</name>
    <message>
        <source>Ground-motion record file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground-motion scale factor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Integration step [s].</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test duration [s].</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--%1: expected a %2 number, found &apos;%3&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>positive</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RunCommand</name>
    <message>
        <source>%1 %  t = %2 s  %3 steps/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hsmu run: link fault at t = %1 s (step %2): %3; reconnecting (attempt %4 of %5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hsmu run: --approval ignored: the configuration has no updating</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hsmu run: connecting to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the test cannot start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hsmu run: test held at t = %1 s (step %2): %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hsmu run: the test stopped unexpectedly (state %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the record could not be written: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: write failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RunOptions</name>
    <message>
        <source>Run a hybrid test headless.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Configuration file or preset name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run an explicit scheme past its stability limit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write PNG plots.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actuator controller: builtin (in-process virtual specimens, the default) or tcp://HOST:PORT (hsmu-controller or a lab controller).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shared secret for the controller.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>After a lost link or a timeout, resume (and reconnect) up to N times before giving up (default 0: hold and exit 2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Decision on update proposals of the onApproval policy: manual, approveAll or rejectAll (default: the configuration&apos;s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expected exactly one CONFIG (a file or a preset name)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--controller: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--reconnect: expected a whole number &gt;= 0, found &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>--approval: expected manual, approveAll or rejectAll, found &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RunReport</name>
    <message>
        <source>  identified parameters of %1 (%2, final value ± std):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  updates applied: %1, proposals pending: %2, final fit error: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  state: %1, steps: %2 of %3, test time: %4 s, wall time: %5 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  peak displacement:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  peak force:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  alarms: none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  alarms:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RunState</name>
    <message>
        <source>no test loaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>paused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>holding</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>finished</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>failed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::AlarmList</name>
    <message>
        <source>limit exceeded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>element fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>integrator fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stability</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>model fit error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fracture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>estimator rejected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>parameter at a bound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>actuator tracking</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>model update</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>info</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>critical</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1 s (step %2) %3: %4</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ControlBar</name>
    <message>
        <source>Test control</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preset: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test configurations shipped with the console</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(choose a preset)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open configuration...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Emergency hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+H</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold the test at once, between two steps (Esc or Ctrl+H)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Speed: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test time per wall-clock time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0.5 x real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>2 x real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>5 x real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>as fast as possible</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::HistoryPlot</name>
    <message>
        <source>Time [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Displacement history</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Displacement [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground acceleration [m/s²]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ground acceleration</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::HysteresisPlot</name>
    <message>
        <source>Deformation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (specimen, measured)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (numerical)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hysteresis of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hysteresis: specimen and numerical twins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotation [%1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deformation [%1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::MainWindow</name>
    <message>
        <source>HSMU Console</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarms and events</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot load %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test configurations (*.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Configuration error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>loaded %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HSMU Console - %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the test cannot start: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ParameterPlot</name>
    <message>
        <source>Time [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>± %1σ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>estimate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>true value</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TestStatusBar</name>
    <message>
        <source>t = %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>step %1 / %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 steps/s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TestWorker</name>
    <message>
        <source>stopped by the operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
