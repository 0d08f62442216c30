<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>CompareCommand</name>
    <message>
        <source>Run the paper's comparison protocol (reference, initial, updated).</source>
        <translation>Run the paper's comparison protocol (reference, initial, updated).</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>The subcommand.</translation>
    </message>
    <message>
        <source>Configuration file or preset name.</source>
        <translation>Configuration file or preset name.</translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation>Output directory.</translation>
    </message>
    <message>
        <source>Write PNG plots.</source>
        <translation>Write PNG plots.</translation>
    </message>
    <message>
        <source>Compared numerical element (default: the first updating target).</source>
        <translation>Compared numerical element (default: the first updating target).</translation>
    </message>
    <message>
        <source>Compared DOF (default: the element's DOF).</source>
        <translation>Compared DOF (default: the element's DOF).</translation>
    </message>
    <message>
        <source>expected exactly one CONFIG (a file or a preset name)</source>
        <translation>expected exactly one CONFIG (a file or a preset name)</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>missing --out DIR</translation>
    </message>
    <message>
        <source>%1 run %2/3: %3 %  (%4 s)</source>
        <translation>%1 run %2/3: %3 %  (%4 s)</translation>
    </message>
    <message>
        <source>%1: the configuration has no online model updating (an enabled "updating" section); compare needs one to run the updated test</source>
        <translation>%1: the configuration has no online model updating (an enabled "updating" section); compare needs one to run the updated test</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1: cannot create the output directory</translation>
    </message>
    <message>
        <source>hsmu compare: three runs (reference, initial, updated) of %1</source>
        <translation>hsmu compare: three runs (reference, initial, updated) of %1</translation>
    </message>
    <message>
        <source>%1: %2 steps, %3</source>
        <translation>%1: %2 steps, %3</translation>
    </message>
    <message>
        <source>hsmu compare: the %1 run stopped at step %2 (state %3)%4</source>
        <translation>hsmu compare: the %1 run stopped at step %2 (state %3)%4</translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation>%1: the plot could not be written</translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation>  outputs: %1</translation>
    </message>
</context>
<context>
    <name>ComparisonPlotExporter</name>
    <message>
        <source>reference</source>
        <translation>reference</translation>
    </message>
    <message>
        <source>initial (not updated)</source>
        <translation>initial (not updated)</translation>
    </message>
    <message>
        <source>updated</source>
        <translation>updated</translation>
    </message>
    <message>
        <source>Hysteresis of %1: reference, initial and updated</source>
        <translation>Hysteresis of %1: reference, initial and updated</translation>
    </message>
    <message>
        <source>Moment history of %1</source>
        <translation>Moment history of %1</translation>
    </message>
    <message>
        <source>Force history of %1</source>
        <translation>Force history of %1</translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation>Moment [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation>Force [%1]</translation>
    </message>
    <message>
        <source>Displacement of %1</source>
        <translation>Displacement of %1</translation>
    </message>
    <message>
        <source>Displacement [m]</source>
        <translation>Displacement [m]</translation>
    </message>
</context>
<context>
    <name>ComparisonTable</name>
    <message>
        <source>Comparison against the reference run: %1 force [%2], %3 displacement [m]</source>
        <translation>Comparison against the reference run: %1 force [%2], %3 displacement [m]</translation>
    </message>
    <message>
        <source>run</source>
        <translation>run</translation>
    </message>
    <message>
        <source>force NRMSE</source>
        <translation>force NRMSE</translation>
    </message>
    <message>
        <source>force peak error [%1]</source>
        <translation>force peak error [%1]</translation>
    </message>
    <message>
        <source>displ. NRMSE</source>
        <translation>displ. NRMSE</translation>
    </message>
    <message>
        <source>displ. peak error [m]</source>
        <translation>displ. peak error [m]</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>steps</translation>
    </message>
    <message>
        <source>initial</source>
        <translation>initial</translation>
    </message>
    <message>
        <source>updated</source>
        <translation>updated</translation>
    </message>
    <message>
        <source>  initial / updated NRMSE: force %1x, displacement %2x</source>
        <translation>  initial / updated NRMSE: force %1x, displacement %2x</translation>
    </message>
    <message>
        <source>Final parameters of the updated run (%1 updates applied):</source>
        <translation>Final parameters of the updated run (%1 updates applied):</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>parameter</translation>
    </message>
    <message>
        <source>value</source>
        <translation>value</translation>
    </message>
    <message>
        <source>std</source>
        <translation>std</translation>
    </message>
    <message>
        <source>true</source>
        <translation>true</translation>
    </message>
</context>
<context>
    <name>ConsoleCommand</name>
    <message>
        <source>Load a preset or configuration and start it.</source>
        <translation>Load a preset or configuration and start it.</translation>
    </message>
    <message>
        <source>Ground-motion record file.</source>
        <translation>Ground-motion record file.</translation>
    </message>
    <message>
        <source>Test time per wall time (0: as fast as possible).</source>
        <translation>Test time per wall time (0: as fast as possible).</translation>
    </message>
    <message>
        <source>Grab the window into this PNG file, then quit.</source>
        <translation>Grab the window into this PNG file, then quit.</translation>
    </message>
    <message>
        <source>Seconds before the screenshot (default 4).</source>
        <translation>Seconds before the screenshot (default 4).</translation>
    </message>
    <message>
        <source>--screenshot-after: expected a number of seconds</source>
        <translation>--screenshot-after: expected a number of seconds</translation>
    </message>
    <message>
        <source>--speed: expected a number</source>
        <translation>--speed: expected a number</translation>
    </message>
    <message>
        <source>HSMU Console: hybrid simulation with online model updating.
Subcommands: run CONFIG --out DIR ..., compare CONFIG --out DIR ..., material --law ... (see hsmu run --help, hsmu compare --help, docs/cli.md).</source>
        <translation>HSMU Console: hybrid simulation with online model updating.
Subcommands: run CONFIG --out DIR ..., compare CONFIG --out DIR ..., material --law ... (see hsmu run --help, hsmu compare --help, docs/cli.md).</translation>
    </message>
    <message>
        <source>unknown subcommand '%1' (expected run, compare or material)</source>
        <translation>unknown subcommand '%1' (expected run, compare or material)</translation>
    </message>
</context>
<context>
    <name>MaterialCommand</name>
    <message>
        <source>Drive one hysteresis law with a deformation history.</source>
        <translation>Drive one hysteresis law with a deformation history.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>The subcommand.</translation>
    </message>
    <message>
        <source>Law: %1.</source>
        <translation>Law: %1.</translation>
    </message>
    <message>
        <source>A law parameter (repeatable).</source>
        <translation>A law parameter (repeatable).</translation>
    </message>
    <message>
        <source>Deformation history (CSV or text).</source>
        <translation>Deformation history (CSV or text).</translation>
    </message>
    <message>
        <source>Output CSV (default: stdout).</source>
        <translation>Output CSV (default: stdout).</translation>
    </message>
    <message>
        <source>unexpected argument '%1'</source>
        <translation>unexpected argument '%1'</translation>
    </message>
    <message>
        <source>missing --law (one of %1)</source>
        <translation>missing --law (one of %1)</translation>
    </message>
    <message>
        <source>missing --history FILE</source>
        <translation>missing --history FILE</translation>
    </message>
    <message>
        <source>--param '%1': expected NAME=VALUE with a finite number</source>
        <translation>--param '%1': expected NAME=VALUE with a finite number</translation>
    </message>
</context>
<context>
    <name>OverrideOptions</name>
    <message>
        <source>Ground-motion record file.</source>
        <translation>Ground-motion record file.</translation>
    </message>
    <message>
        <source>Ground-motion scale factor.</source>
        <translation>Ground-motion scale factor.</translation>
    </message>
    <message>
        <source>Integration step [s].</source>
        <translation>Integration step [s].</translation>
    </message>
    <message>
        <source>Test duration [s].</source>
        <translation>Test duration [s].</translation>
    </message>
    <message>
        <source>--%1: expected a %2 number, found '%3'</source>
        <translation>--%1: expected a %2 number, found '%3'</translation>
    </message>
    <message>
        <source>positive</source>
        <translation>positive</translation>
    </message>
</context>
<context>
    <name>RunCommand</name>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1: cannot create the output directory</translation>
    </message>
    <message>
        <source>the test cannot start: %1</source>
        <translation>the test cannot start: %1</translation>
    </message>
    <message>
        <source>%1 %  t = %2 s  %3 steps/s</source>
        <translation>%1 %  t = %2 s  %3 steps/s</translation>
    </message>
    <message>
        <source>hsmu run: test held at t = %1 s (step %2): %3</source>
        <translation>hsmu run: test held at t = %1 s (step %2): %3</translation>
    </message>
    <message>
        <source>hsmu run: the test stopped unexpectedly (state %1)</source>
        <translation>hsmu run: the test stopped unexpectedly (state %1)</translation>
    </message>
    <message>
        <source>%1: write failed</source>
        <translation>%1: write failed</translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation>%1: the plot could not be written</translation>
    </message>
    <message>
        <source>hsmu run: link fault at t = %1 s (step %2): %3; reconnecting (attempt %4 of %5)</source>
        <translation>hsmu run: link fault at t = %1 s (step %2): %3; reconnecting (attempt %4 of %5)</translation>
    </message>
    <message>
        <source>hsmu run: --approval ignored: the configuration has no updating</source>
        <translation>hsmu run: --approval ignored: the configuration has no updating</translation>
    </message>
    <message>
        <source>hsmu run: connecting to %1</source>
        <translation>hsmu run: connecting to %1</translation>
    </message>
    <message>
        <source>%1: the record could not be written: %2</source>
        <translation>%1: the record could not be written: %2</translation>
    </message>
</context>
<context>
    <name>RunOptions</name>
    <message>
        <source>Run a hybrid test headless.</source>
        <translation>Run a hybrid test headless.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>The subcommand.</translation>
    </message>
    <message>
        <source>Configuration file or preset name.</source>
        <translation>Configuration file or preset name.</translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation>Output directory.</translation>
    </message>
    <message>
        <source>Run an explicit scheme past its stability limit.</source>
        <translation>Run an explicit scheme past its stability limit.</translation>
    </message>
    <message>
        <source>Write PNG plots.</source>
        <translation>Write PNG plots.</translation>
    </message>
    <message>
        <source>Actuator controller: builtin (in-process virtual specimens, the default) or tcp://HOST:PORT (hsmu-controller or a lab controller).</source>
        <translation>Actuator controller: builtin (in-process virtual specimens, the default) or tcp://HOST:PORT (hsmu-controller or a lab controller).</translation>
    </message>
    <message>
        <source>Shared secret for the controller.</source>
        <translation>Shared secret for the controller.</translation>
    </message>
    <message>
        <source>After a lost link or a timeout, resume (and reconnect) up to N times before giving up (default 0: hold and exit 2).</source>
        <translation>After a lost link or a timeout, resume (and reconnect) up to N times before giving up (default 0: hold and exit 2).</translation>
    </message>
    <message>
        <source>Decision on update proposals of the onApproval policy: manual, approveAll or rejectAll (default: the configuration's).</source>
        <translation>Decision on update proposals of the onApproval policy: manual, approveAll or rejectAll (default: the configuration's).</translation>
    </message>
    <message>
        <source>expected exactly one CONFIG (a file or a preset name)</source>
        <translation>expected exactly one CONFIG (a file or a preset name)</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>missing --out DIR</translation>
    </message>
    <message>
        <source>--controller: %1</source>
        <translation>--controller: %1</translation>
    </message>
    <message>
        <source>--reconnect: expected a whole number &gt;= 0, found '%1'</source>
        <translation>--reconnect: expected a whole number &gt;= 0, found '%1'</translation>
    </message>
    <message>
        <source>--approval: expected manual, approveAll or rejectAll, found '%1'</source>
        <translation>--approval: expected manual, approveAll or rejectAll, found '%1'</translation>
    </message>
</context>
<context>
    <name>RunReport</name>
    <message>
        <source>  identified parameters of %1 (%2, final value ± std):</source>
        <translation>  identified parameters of %1 (%2, final value ± std):</translation>
    </message>
    <message>
        <source>  updates applied: %1, proposals pending: %2, final fit error: %3</source>
        <translation>  updates applied: %1, proposals pending: %2, final fit error: %3</translation>
    </message>
    <message>
        <source>Test: %1</source>
        <translation>Test: %1</translation>
    </message>
    <message>
        <source>  state: %1, steps: %2 of %3, test time: %4 s, wall time: %5 s</source>
        <translation>  state: %1, steps: %2 of %3, test time: %4 s, wall time: %5 s</translation>
    </message>
    <message>
        <source>  peak displacement:</source>
        <translation>  peak displacement:</translation>
    </message>
    <message>
        <source>  peak force:</source>
        <translation>  peak force:</translation>
    </message>
    <message>
        <source>  alarms: none</source>
        <translation>  alarms: none</translation>
    </message>
    <message>
        <source>  alarms:</source>
        <translation>  alarms:</translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation>  outputs: %1</translation>
    </message>
</context>
<context>
    <name>RunState</name>
    <message>
        <source>no test loaded</source>
        <translation>no test loaded</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>ready</translation>
    </message>
    <message>
        <source>running</source>
        <translation>running</translation>
    </message>
    <message>
        <source>paused</source>
        <translation>paused</translation>
    </message>
    <message>
        <source>holding</source>
        <translation>holding</translation>
    </message>
    <message>
        <source>finished</source>
        <translation>finished</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>stopped</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>failed</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::AlarmList</name>
    <message>
        <source>limit exceeded</source>
        <translation>limit exceeded</translation>
    </message>
    <message>
        <source>control fault</source>
        <translation>control fault</translation>
    </message>
    <message>
        <source>element fault</source>
        <translation>element fault</translation>
    </message>
    <message>
        <source>integrator fault</source>
        <translation>integrator fault</translation>
    </message>
    <message>
        <source>operator</source>
        <translation>operator</translation>
    </message>
    <message>
        <source>stability</source>
        <translation>stability</translation>
    </message>
    <message>
        <source>info</source>
        <translation>info</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>warning</translation>
    </message>
    <message>
        <source>critical</source>
        <translation>critical</translation>
    </message>
    <message>
        <source>t = %1 s (step %2) %3: %4</source>
        <translation>t = %1 s (step %2) %3: %4</translation>
    </message>
    <message>
        <source>model fit error</source>
        <translation>model fit error</translation>
    </message>
    <message>
        <source>fracture</source>
        <translation>fracture</translation>
    </message>
    <message>
        <source>estimator rejected</source>
        <translation>estimator rejected</translation>
    </message>
    <message>
        <source>parameter at a bound</source>
        <translation>parameter at a bound</translation>
    </message>
    <message>
        <source>actuator tracking</source>
        <translation>actuator tracking</translation>
    </message>
    <message>
        <source>model update</source>
        <translation>model update</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ControlBar</name>
    <message>
        <source>Test control</source>
        <translation>Test control</translation>
    </message>
    <message>
        <source>Preset: </source>
        <translation>Preset: </translation>
    </message>
    <message>
        <source>Test configurations shipped with the console</source>
        <translation>Test configurations shipped with the console</translation>
    </message>
    <message>
        <source>(choose a preset)</source>
        <translation>(choose a preset)</translation>
    </message>
    <message>
        <source>Open configuration...</source>
        <translation>Open configuration...</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Resume</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Emergency hold</source>
        <translation>Emergency hold</translation>
    </message>
    <message>
        <source>Ctrl+H</source>
        <translation>Ctrl+H</translation>
    </message>
    <message>
        <source>Hold the test at once, between two steps (Esc or Ctrl+H)</source>
        <translation>Hold the test at once, between two steps (Esc or Ctrl+H)</translation>
    </message>
    <message>
        <source> Speed: </source>
        <translation> Speed: </translation>
    </message>
    <message>
        <source>Test time per wall-clock time</source>
        <translation>Test time per wall-clock time</translation>
    </message>
    <message>
        <source>0.5 x real time</source>
        <translation>0.5 x real time</translation>
    </message>
    <message>
        <source>real time</source>
        <translation>real time</translation>
    </message>
    <message>
        <source>2 x real time</source>
        <translation>2 x real time</translation>
    </message>
    <message>
        <source>5 x real time</source>
        <translation>5 x real time</translation>
    </message>
    <message>
        <source>as fast as possible</source>
        <translation>as fast as possible</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::HistoryPlot</name>
    <message>
        <source>Time [s]</source>
        <translation>Time [s]</translation>
    </message>
    <message>
        <source>Displacement history</source>
        <translation>Displacement history</translation>
    </message>
    <message>
        <source>Displacement [m]</source>
        <translation>Displacement [m]</translation>
    </message>
    <message>
        <source>Ground motion</source>
        <translation>Ground motion</translation>
    </message>
    <message>
        <source>Ground acceleration [m/s²]</source>
        <translation>Ground acceleration [m/s²]</translation>
    </message>
    <message>
        <source>Ground acceleration</source>
        <translation>Ground acceleration</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::HysteresisPlot</name>
    <message>
        <source>Deformation</source>
        <translation>Deformation</translation>
    </message>
    <message>
        <source>Force</source>
        <translation>Force</translation>
    </message>
    <message>
        <source>%1 (specimen, measured)</source>
        <translation>%1 (specimen, measured)</translation>
    </message>
    <message>
        <source>%1 (numerical)</source>
        <translation>%1 (numerical)</translation>
    </message>
    <message>
        <source>Rotation [%1]</source>
        <translation>Rotation [%1]</translation>
    </message>
    <message>
        <source>Deformation [%1]</source>
        <translation>Deformation [%1]</translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation>Moment [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation>Force [%1]</translation>
    </message>
    <message>
        <source>Hysteresis of %1</source>
        <translation>Hysteresis of %1</translation>
    </message>
    <message>
        <source>Hysteresis: specimen and numerical twins</source>
        <translation>Hysteresis: specimen and numerical twins</translation>
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
        <translation>Alarms and events</translation>
    </message>
    <message>
        <source>cannot load %1: %2</source>
        <translation>cannot load %1: %2</translation>
    </message>
    <message>
        <source>Open configuration</source>
        <translation>Open configuration</translation>
    </message>
    <message>
        <source>Test configurations (*.json);;All files (*)</source>
        <translation>Test configurations (*.json);;All files (*)</translation>
    </message>
    <message>
        <source>Configuration error</source>
        <translation>Configuration error</translation>
    </message>
    <message>
        <source>loaded %1 (%2)</source>
        <translation>loaded %1 (%2)</translation>
    </message>
    <message>
        <source>HSMU Console - %1</source>
        <translation>HSMU Console - %1</translation>
    </message>
    <message>
        <source>the test cannot start: %1</source>
        <translation>the test cannot start: %1</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ParameterPlot</name>
    <message>
        <source>Time [s]</source>
        <translation>Time [s]</translation>
    </message>
    <message>
        <source>± %1σ</source>
        <translation>± %1σ</translation>
    </message>
    <message>
        <source>estimate</source>
        <translation>estimate</translation>
    </message>
    <message>
        <source>true value</source>
        <translation>true value</translation>
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
        <translation>step %1 / %2</translation>
    </message>
    <message>
        <source>%1 steps/s</source>
        <translation>%1 steps/s</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TestWorker</name>
    <message>
        <source>stopped by the operator</source>
        <translation>stopped by the operator</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>emergency hold by the operator</translation>
    </message>
</context>
</TS>
