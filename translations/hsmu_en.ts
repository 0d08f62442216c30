<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>ActuatorLimitText</name>
    <message>
        <source>%1, actuator &apos;%2&apos; (%3)</source>
        <translation>%1, actuator &apos;%2&apos; (%3)</translation>
    </message>
    <message>
        <source>force control</source>
        <translation>force control</translation>
    </message>
    <message>
        <source>displacement control</source>
        <translation>displacement control</translation>
    </message>
    <message>
        <source>stroke |s|</source>
        <translation>stroke |s|</translation>
    </message>
    <message>
        <source>force |F|</source>
        <translation>force |F|</translation>
    </message>
    <message>
        <source>stroke increment |Δs| per step</source>
        <translation>stroke increment |Δs| per step</translation>
    </message>
    <message>
        <source>PASS  %1: %2 up to %3 %4 (t = %5 s), within the limit %6 %4</source>
        <translation>PASS  %1: %2 up to %3 %4 (t = %5 s), within the limit %6 %4</translation>
    </message>
    <message>
        <source>FAIL  %1: %2 reaches %3 %4 (t = %5 s), past the limit %6 %4: the test will hold at that step</source>
        <translation>FAIL  %1: %2 reaches %3 %4 (t = %5 s), past the limit %6 %4: the test will hold at that step</translation>
    </message>
    <message>
        <source>%1: %2 limit %3 %4, checked at every step (it depends on the specimen&apos;s response)</source>
        <translation>%1: %2 limit %3 %4, checked at every step (it depends on the specimen&apos;s response)</translation>
    </message>
    <message>
        <source>%1: no %2 limit</source>
        <translation>%1: no %2 limit</translation>
    </message>
</context>
<context>
    <name>AlarmText</name>
    <message>
        <source>test resumed after an automatic reconnect</source>
        <translation>test resumed after an automatic reconnect</translation>
    </message>
    <message>
        <source>operator hold</source>
        <translation>operator hold</translation>
    </message>
    <message>
        <source>predicted displacement is not finite</source>
        <translation>predicted displacement is not finite</translation>
    </message>
    <message>
        <source>restoring force or response is not finite</source>
        <translation>restoring force or response is not finite</translation>
    </message>
    <message>
        <source>test held: %1</source>
        <translation>test held: %1</translation>
    </message>
    <message>
        <source>test resumed</source>
        <translation>test resumed</translation>
    </message>
    <message>
        <source>model error %1 % above the threshold %2 %</source>
        <translation>model error %1 % above the threshold %2 %</translation>
    </message>
    <message>
        <source>sudden strength loss: measured force %1 short of the model's by %2</source>
        <translation>sudden strength loss: measured force %1 short of the model's by %2</translation>
    </message>
    <message>
        <source>identification step rejected: %1</source>
        <translation>identification step rejected: %1</translation>
    </message>
    <message>
        <source>actuator tracking error J2 = %1 % (delay J1 = %2 s)</source>
        <translation>actuator tracking error J2 = %1 % (delay J1 = %2 s)</translation>
    </message>
    <message>
        <source>%1 has been at its bound %2 for %3 s</source>
        <translation>%1 has been at its bound %2 for %3 s</translation>
    </message>
    <message>
        <source>update not applied: the approval queue is full (%1 proposals pending); this and later offers are in the record until the operator decides</source>
        <translation>update not applied: the approval queue is full (%1 proposals pending); this and later offers are in the record until the operator decides</translation>
    </message>
    <message>
        <source>offsets proposed for the twins: u0 = %1, F0 = %2 (they apply only when the operator approves them)</source>
        <translation>offsets proposed for the twins: u0 = %1, F0 = %2 (they apply only when the operator approves them)</translation>
    </message>
    <message>
        <source>%1: omega_max dt = %2 (omega_max = %3 rad/s, dt = %4 s) within the limit %5</source>
        <translation>%1: omega_max dt = %2 (omega_max = %3 rad/s, dt = %4 s) within the limit %5</translation>
    </message>
    <message>
        <source>%1 is unstable for this model: omega_max dt = %2 exceeds %3 (omega_max = %4 rad/s, dt = %5 s); use dt &lt;= %6 s or the alphaOS integrator</source>
        <translation>%1 is unstable for this model: omega_max dt = %2 exceeds %3 (omega_max = %4 rad/s, dt = %5 s); use dt &lt;= %6 s or the alphaOS integrator</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>operator</source>
        <translation>operator</translation>
    </message>
    <message>
        <source>operator at the console</source>
        <translation>operator at the console</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>emergency hold by the operator</translation>
    </message>
    <message>
        <source>emergency hold: %1 (%2)</source>
        <translation>emergency hold: %1 (%2)</translation>
    </message>
    <message>
        <source>emergency hold: %1</source>
        <translation>emergency hold: %1</translation>
    </message>
    <message>
        <source>target deformation is not a finite number</source>
        <translation>target deformation is not a finite number</translation>
    </message>
    <message>
        <source>target deformation |d| = %1 exceeds the limit %2</source>
        <translation>target deformation |d| = %1 exceeds the limit %2</translation>
    </message>
    <message>
        <source>target increment |d - d_last| = %1 exceeds the limit %2</source>
        <translation>target increment |d - d_last| = %1 exceeds the limit %2</translation>
    </message>
    <message>
        <source>measured force is not a finite number</source>
        <translation>measured force is not a finite number</translation>
    </message>
    <message>
        <source>measured force |F| = %1 exceeds the limit %2</source>
        <translation>measured force |F| = %1 exceeds the limit %2</translation>
    </message>
    <message>
        <source>measured deformation is not a finite number</source>
        <translation>measured deformation is not a finite number</translation>
    </message>
    <message>
        <source>measured deformation |d| = %1 exceeds the limit %2 (+%3 % tolerance)</source>
        <translation>measured deformation |d| = %1 exceeds the limit %2 (+%3 % tolerance)</translation>
    </message>
    <message>
        <source>%1 (forced by the operator)</source>
        <translation>%1 (forced by the operator)</translation>
    </message>
    <message>
        <source>updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), limit %4; K0 and damping kept from the start: the explicit integration of the updated model may diverge</source>
        <translation>updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), limit %4; K0 and damping kept from the start: the explicit integration of the updated model may diverge</translation>
    </message>
    <message>
        <source>updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), limit %4; K0 and damping kept from the start</source>
        <translation>updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), limit %4; K0 and damping kept from the start</translation>
    </message>
    <message>
        <source>auxiliary model did not converge at deformation %1</source>
        <translation>auxiliary model did not converge at deformation %1</translation>
    </message>
    <message>
        <source>stopped by the operator</source>
        <translation>stopped by the operator</translation>
    </message>
    <message>
        <source>synthetic Kanai-Tajimi (seed %1)</source>
        <translation>synthetic Kanai-Tajimi (seed %1)</translation>
    </message>
    <message>
        <source>link to %1 is down (%2); resume to reconnect</source>
        <translation>link to %1 is down (%2); resume to reconnect</translation>
    </message>
    <message>
        <source>link to %1: %2</source>
        <translation>link to %1: %2</translation>
    </message>
    <message>
        <source>controller at %1: %2</source>
        <translation>controller at %1: %2</translation>
    </message>
    <message>
        <source>TCP link is holding: %1</source>
        <translation>TCP link is holding: %1</translation>
    </message>
    <message>
        <source>no connection to %1 within %2 s</source>
        <translation>no connection to %1 within %2 s</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>cannot connect to %1: %2</translation>
    </message>
    <message>
        <source>cannot resolve %1: %2</source>
        <translation>cannot resolve %1: %2</translation>
    </message>
    <message>
        <source>the controller closed the connection</source>
        <translation>the controller closed the connection</translation>
    </message>
    <message>
        <source>the peer closed the connection</source>
        <translation>the peer closed the connection</translation>
    </message>
    <message>
        <source>connection lost while sending: %1</source>
        <translation>connection lost while sending: %1</translation>
    </message>
    <message>
        <source>connection lost: %1</source>
        <translation>connection lost: %1</translation>
    </message>
    <message>
        <source>malformed frame from the controller: %1</source>
        <translation>malformed frame from the controller: %1</translation>
    </message>
    <message>
        <source>the controller was silent for %1 s</source>
        <translation>the controller was silent for %1 s</translation>
    </message>
    <message>
        <source>not connected: %1</source>
        <translation>not connected: %1</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>not connected</translation>
    </message>
    <message>
        <source>no reply within %1 s</source>
        <translation>no reply within %1 s</translation>
    </message>
    <message>
        <source>closed by the console</source>
        <translation>closed by the console</translation>
    </message>
    <message>
        <source>closed by an emergency hold</source>
        <translation>closed by an emergency hold</translation>
    </message>
    <message>
        <source>no answer to the hello</source>
        <translation>no answer to the hello</translation>
    </message>
    <message>
        <source>no measurement for step %1</source>
        <translation>no measurement for step %1</translation>
    </message>
    <message>
        <source>the controller's specimen is at step %1 but the test committed %2 (was it restarted without its --state file?); cannot resume without a jump</source>
        <translation>the controller's specimen is at step %1 but the test committed %2 (was it restarted without its --state file?); cannot resume without a jump</translation>
    </message>
    <message>
        <source>specimen '%1' holds: %2</source>
        <translation>specimen '%1' holds: %2</translation>
    </message>
    <message>
        <source>interlock: %1</source>
        <translation>interlock: %1</translation>
    </message>
    <message>
        <source>specimen fault: %1</source>
        <translation>specimen fault: %1</translation>
    </message>
    <message>
        <source>controller fault: %1</source>
        <translation>controller fault: %1</translation>
    </message>
    <message>
        <source>actuator position |d| = %1 exceeds the limit %2</source>
        <translation>actuator position |d| = %1 exceeds the limit %2</translation>
    </message>
    <message>
        <source>console hold</source>
        <translation>console hold</translation>
    </message>
    <message>
        <source>wrong token</source>
        <translation>wrong token</translation>
    </message>
    <message>
        <source>another console session is running a test on this controller (one session at a time)</source>
        <translation>another console session is running a test on this controller (one session at a time)</translation>
    </message>
    <message>
        <source>this controller has no specimen named '%1'</source>
        <translation>this controller has no specimen named '%1'</translation>
    </message>
    <message>
        <source>held from the previous console session: %1</source>
        <translation>held from the previous console session: %1</translation>
    </message>
    <message>
        <source>virtual specimen (%1 law, force noise std %2, %3 actuator, fracture event)</source>
        <translation>virtual specimen (%1 law, force noise std %2, %3 actuator, fracture event)</translation>
    </message>
    <message>
        <source>virtual specimen (%1 law, force noise std %2, %3 actuator)</source>
        <translation>virtual specimen (%1 law, force noise std %2, %3 actuator)</translation>
    </message>
    <message>
        <source>specimen '%1' on hsmu-controller (%2 law, force noise std %3, %4 actuator, %5 pace, %6 Hz predictor-corrector, fracture event), %7 committed steps</source>
        <translation>specimen '%1' on hsmu-controller (%2 law, force noise std %3, %4 actuator, %5 pace, %6 Hz predictor-corrector, fracture event), %7 committed steps</translation>
    </message>
    <message>
        <source>specimen '%1' on hsmu-controller (%2 law, force noise std %3, %4 actuator, %5 pace, %6 Hz predictor-corrector), %7 committed steps</source>
        <translation>specimen '%1' on hsmu-controller (%2 law, force noise std %3, %4 actuator, %5 pace, %6 Hz predictor-corrector), %7 committed steps</translation>
    </message>
    <message>
        <source>TCP link %1 to %2</source>
        <translation>TCP link %1 to %2</translation>
    </message>
    <message>
        <source>specimen '%1'</source>
        <translation>specimen '%1'</translation>
    </message>
    <message>
        <source>%1 link %2 for specimen '%3' (%4)</source>
        <translation>%1 link %2 for specimen '%3' (%4)</translation>
    </message>
    <message>
        <source>prediction rejected: %1</source>
        <translation>prediction rejected: %1</translation>
    </message>
    <message>
        <source>update rejected: %1</source>
        <translation>update rejected: %1</translation>
    </message>
    <message>
        <source>Bouc-Wen integration failed (%1): %2</source>
        <translation>Bouc-Wen integration failed (%1): %2</translation>
    </message>
    <message>
        <source>%1; z and e could not be advanced either: step skipped</source>
        <translation>%1; z and e could not be advanced either: step skipped</translation>
    </message>
    <message>
        <source>the state is not finite</source>
        <translation>the state is not finite</translation>
    </message>
    <message>
        <source>the measurement is not finite</source>
        <translation>the measurement is not finite</translation>
    </message>
    <message>
        <source>the predicted measurement is not finite</source>
        <translation>the predicted measurement is not finite</translation>
    </message>
    <message>
        <source>the innovation covariance is not positive definite (check R)</source>
        <translation>the innovation covariance is not positive definite (check R)</translation>
    </message>
    <message>
        <source>the filter has not been initialized</source>
        <translation>the filter has not been initialized</translation>
    </message>
    <message>
        <source>Nelder-Mead fit failed: %1</source>
        <translation>Nelder-Mead fit failed: %1</translation>
    </message>
    <message>
        <source>Nelder-Mead trigger %1 kept the parameters (RMS %2 not improved, %3 evaluations, %4 ms)</source>
        <translation>Nelder-Mead trigger %1 kept the parameters (RMS %2 not improved, %3 evaluations, %4 ms)</translation>
    </message>
    <message>
        <source>Nelder-Mead trigger %1: RMS force error %2 -&gt; %3 (%4 evaluations, %5 ms)</source>
        <translation>Nelder-Mead trigger %1: RMS force error %2 -&gt; %3 (%4 evaluations, %5 ms)</translation>
    </message>
    <message>
        <source>the measured deformation or force is not finite: step skipped</source>
        <translation>the measured deformation or force is not finite: step skipped</translation>
    </message>
    <message>
        <source>%1 line %2: %3</source>
        <translation>%1 line %2: %3</translation>
    </message>
    <message>
        <source>cannot open '%1': the file does not exist</source>
        <translation>cannot open '%1': the file does not exist</translation>
    </message>
    <message>
        <source>cannot open '%1': it is a folder, not a file</source>
        <translation>cannot open '%1': it is a folder, not a file</translation>
    </message>
    <message>
        <source>cannot read '%1': not a regular file (a device, pipe or socket)</source>
        <translation>cannot read '%1': not a regular file (a device, pipe or socket)</translation>
    </message>
    <message>
        <source>cannot open '%1' for reading (permissions?)</source>
        <translation>cannot open '%1' for reading (permissions?)</translation>
    </message>
    <message>
        <source>'%1' is not a text file (binary data at byte %2)</source>
        <translation>'%1' is not a text file (binary data at byte %2)</translation>
    </message>
    <message>
        <source>the file is empty (expected a PEER AT2 record)</source>
        <translation>the file is empty (expected a PEER AT2 record)</translation>
    </message>
    <message>
        <source>the file is empty (no acceleration values)</source>
        <translation>the file is empty (no acceleration values)</translation>
    </message>
    <message>
        <source>no data lines (only comments or blank lines)</source>
        <translation>no data lines (only comments or blank lines)</translation>
    </message>
    <message>
        <source>the file is empty: expected an AT2 header ('NPTS=..., DT=...' on line 4), two columns (time, acceleration) or one column of values</source>
        <translation>the file is empty: expected an AT2 header ('NPTS=..., DT=...' on line 4), two columns (time, acceleration) or one column of values</translation>
    </message>
    <message>
        <source>no data lines: expected an AT2 header ('NPTS=..., DT=...' on line 4), two columns (time, acceleration) or one column of values</source>
        <translation>no data lines: expected an AT2 header ('NPTS=..., DT=...' on line 4), two columns (time, acceleration) or one column of values</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>expected a number, found %1</translation>
    </message>
    <message>
        <source>non-finite value %1</source>
        <translation>non-finite value %1</translation>
    </message>
    <message>
        <source>the time step dt must be &gt; 0 s, got %1</source>
        <translation>the time step dt must be &gt; 0 s, got %1</translation>
    </message>
    <message>
        <source>expected two columns (time, acceleration), found %1 value(s)</source>
        <translation>expected two columns (time, acceleration), found %1 value(s)</translation>
    </message>
    <message>
        <source>only one sample: the time step cannot be determined</source>
        <translation>only one sample: the time step cannot be determined</translation>
    </message>
    <message>
        <source>time must increase: %1 s follows %2 s</source>
        <translation>time must increase: %1 s follows %2 s</translation>
    </message>
    <message>
        <source>non-uniform time step: %1 s follows %2 s (step %3 s, mean step %4 s); a uniform step is required (tolerance 1e-6 relative)</source>
        <translation>non-uniform time step: %1 s follows %2 s (step %3 s, mean step %4 s); a uniform step is required (tolerance 1e-6 relative)</translation>
    </message>
    <message>
        <source>a single column of acceleration values needs the time step dt, and none was given</source>
        <translation>a single column of acceleration values needs the time step dt, and none was given</translation>
    </message>
    <message>
        <source>cannot open the configuration file</source>
        <translation>cannot open the configuration file</translation>
    </message>
    <message>
        <source>not a regular file (a folder, device, pipe or socket)</source>
        <translation>not a regular file (a folder, device, pipe or socket)</translation>
    </message>
    <message>
        <source>not valid JSON (%1)</source>
        <translation>not valid JSON (%1)</translation>
    </message>
    <message>
        <source>cannot be opened (no such file)</source>
        <translation>cannot be opened (no such file)</translation>
    </message>
    <message>
        <source>not an HSMU record (not an HDF5 file)</source>
        <translation>not an HSMU record (not an HDF5 file)</translation>
    </message>
    <message>
        <source>not an HSMU record (no schema_version attribute)</source>
        <translation>not an HSMU record (no schema_version attribute)</translation>
    </message>
    <message>
        <source>damaged record (%1)</source>
        <translation>damaged record (%1)</translation>
    </message>
    <message>
        <source>ideal</source>
        <translation>ideal</translation>
    </message>
    <message>
        <source>lag</source>
        <translation>lag</translation>
    </message>
    <message>
        <source>delay</source>
        <translation>delay</translation>
    </message>
    <message>
        <source>fast</source>
        <translation>fast</translation>
    </message>
    <message>
        <source>real-time</source>
        <translation>real-time</translation>
    </message>
    <message>
        <source>the record holds no step</source>
        <translation>the record holds no step</translation>
    </message>
    <message>
        <source>RTHS run held: %1</source>
        <translation>RTHS run held: %1</translation>
    </message>
    <message>
        <source>live delay J1 = %1 ms over the warning threshold %2 ms</source>
        <translation>live delay J1 = %1 ms over the warning threshold %2 ms</translation>
    </message>
    <message>
        <source>live delay J1 = %1 ms over the critical threshold %2 ms</source>
        <translation>live delay J1 = %1 ms over the critical threshold %2 ms</translation>
    </message>
    <message>
        <source>live tracking error J2 = %1 % over the warning threshold %2 %</source>
        <translation>live tracking error J2 = %1 % over the warning threshold %2 %</translation>
    </message>
    <message>
        <source>live tracking error J2 = %1 % over the critical threshold %2 %</source>
        <translation>live tracking error J2 = %1 % over the critical threshold %2 %</translation>
    </message>
    <message>
        <source>RTHS run not followed: %1</source>
        <translation>RTHS run not followed: %1</translation>
    </message>
</context>
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
    <message>
        <source>--plots: this program cannot draw (run it through hsmu)</source>
        <translation>--plots: this program cannot draw (run it through hsmu)</translation>
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
    <message>
        <source>reference</source>
        <translation>reference</translation>
    </message>
    <message>
        <source>element</source>
        <translation>element</translation>
    </message>
    <message>
        <source>basic DOF</source>
        <translation>basic DOF</translation>
    </message>
    <message>
        <source>deformation NRMSE</source>
        <translation>deformation NRMSE</translation>
    </message>
    <message>
        <source>deformation peak error</source>
        <translation>deformation peak error</translation>
    </message>
    <message>
        <source>force peak error</source>
        <translation>force peak error</translation>
    </message>
    <message>
        <source>Per basic DOF against the reference run:</source>
        <translation>Per basic DOF against the reference run:</translation>
    </message>
    <message>
        <source>actuator</source>
        <translation>actuator</translation>
    </message>
    <message>
        <source>control</source>
        <translation>control</translation>
    </message>
    <message>
        <source>force</source>
        <translation>force</translation>
    </message>
    <message>
        <source>displacement</source>
        <translation>displacement</translation>
    </message>
    <message>
        <source>Per actuator: tracking against its command, force against the reference run:</source>
        <translation>Per actuator: tracking against its command, force against the reference run:</translation>
    </message>
</context>
<context>
    <name>ConsoleCommand</name>
    <message>
        <source>The record's own sample step [s] (a one-column file of values needs it).</source>
        <translation>The record's own sample step [s] (a one-column file of values needs it).</translation>
    </message>
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
    <message>
        <source>Actuator controller: builtin (the default) or tcp://HOST:PORT.</source>
        <translation>Actuator controller: builtin (the default) or tcp://HOST:PORT.</translation>
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
        <translation>Write a run record (HDF5) as CSV files, one per group.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>The subcommand.</translation>
    </message>
    <message>
        <source>The record (record.h5).</source>
        <translation>The record (record.h5).</translation>
    </message>
    <message>
        <source>Output directory for the CSVs.</source>
        <translation>Output directory for the CSVs.</translation>
    </message>
    <message>
        <source>expected exactly one FILE.h5</source>
        <translation>expected exactly one FILE.h5</translation>
    </message>
    <message>
        <source>missing --csv DIR</source>
        <translation>missing --csv DIR</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1: cannot create the output directory</translation>
    </message>
    <message>
        <source>%1 steps, %2 alarms; written:</source>
        <translation>%1 steps, %2 alarms; written:</translation>
    </message>
    <message>
        <source>Units of the CSV columns, e.g. length=in,force=kip,rotation=deg,moment=kip*in,time=ms (length: m, cm, mm, in, ft; force: N, kN, MN, lbf, kip, kgf, tonf; rotation: rad, mrad, deg; moment: a force unit times a length unit; time: s, ms). Default: kN, m, s, rad.</source>
        <translation>Units of the CSV columns, e.g. length=in,force=kip,rotation=deg,moment=kip*in,time=ms (length: m, cm, mm, in, ft; force: N, kN, MN, lbf, kip, kgf, tonf; rotation: rad, mrad, deg; moment: a force unit times a length unit; time: s, ms). Default: kN, m, s, rad.</translation>
    </message>
</context>
<context>
    <name>GroundMotionCheck</name>
    <message>
        <source>%1 is not a text file of numbers (it holds binary data, e.g. an image); expected a PEER AT2 record, two columns (time, acceleration) or one column of values</source>
        <translation>%1 is not a text file of numbers (it holds binary data, e.g. an image); expected a PEER AT2 record, two columns (time, acceleration) or one column of values</translation>
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
    <message>
        <source>Time step [s] between the points of a one-column history (a rate-dependent law).</source>
        <translation>Time step [s] between the points of a one-column history (a rate-dependent law).</translation>
    </message>
    <message>
        <source>--dt '%1': expected a time step &gt; 0 in seconds</source>
        <translation>--dt '%1': expected a time step &gt; 0 in seconds</translation>
    </message>
    <message>
        <source>--dt: the history has its own time column</source>
        <translation>--dt: the history has its own time column</translation>
    </message>
    <message>
        <source>%1 is rate-dependent: give the history a time column (time, deformation) or --dt</source>
        <translation>%1 is rate-dependent: give the history a time column (time, deformation) or --dt</translation>
    </message>
</context>
<context>
    <name>MethodComparisonTable</name>
    <message>
        <source>Method comparison on %1: %2 samples</source>
        <translation>Method comparison on %1: %2 samples</translation>
    </message>
    <message>
        <source>method</source>
        <translation>method</translation>
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
        <translation>on bounds</translation>
    </message>
    <message>
        <source>rejected</source>
        <translation>rejected</translation>
    </message>
    <message>
        <source>verdict</source>
        <translation>verdict</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>  recommended: %1 (the cheapest within 5 % of the best NRMSE)</source>
        <translation>  recommended: %1 (the cheapest within 5 % of the best NRMSE)</translation>
    </message>
    <message>
        <source>  verdict: %1</source>
        <translation>  verdict: %1</translation>
    </message>
    <message>
        <source>  outputs: %1 (comparison.csv, summary.json; each method's own files in calibration/, ukf/, nelder-mead/)</source>
        <translation>  outputs: %1 (comparison.csv, summary.json; each method's own files in calibration/, ukf/, nelder-mead/)</translation>
    </message>
</context>
<context>
    <name>OperatorEvent</name>
    <message>
        <source>pre-flight confirmed by the operator (zero offsets)</source>
        <translation>pre-flight confirmed by the operator (zero offsets)</translation>
    </message>
    <message>
        <source>test started by the operator</source>
        <translation>test started by the operator</translation>
    </message>
    <message>
        <source>paused by the operator</source>
        <translation>paused by the operator</translation>
    </message>
    <message>
        <source>single step by the operator</source>
        <translation>single step by the operator</translation>
    </message>
    <message>
        <source>resumed by the operator</source>
        <translation>resumed by the operator</translation>
    </message>
    <message>
        <source>emergency hold before the test was armed: nothing is armed, the pre-flight check must be confirmed again</source>
        <translation>emergency hold before the test was armed: nothing is armed, the pre-flight check must be confirmed again</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>emergency hold by the operator</translation>
    </message>
    <message>
        <source>test ended by the operator, data kept</source>
        <translation>test ended by the operator, data kept</translation>
    </message>
    <message>
        <source>update %1 approved by the operator: %2 -&gt; %3</source>
        <translation>update %1 approved by the operator: %2 -&gt; %3</translation>
    </message>
    <message>
        <source>update %1 rejected by the operator (%2)</source>
        <translation>update %1 rejected by the operator (%2)</translation>
    </message>
    <message>
        <source>offsets %1 approved by the operator for %2: %3</source>
        <translation>offsets %1 approved by the operator for %2: %3</translation>
    </message>
    <message>
        <source>offsets %1 rejected by the operator (%2)</source>
        <translation>offsets %1 rejected by the operator (%2)</translation>
    </message>
    <message>
        <source>bounds changed: %1 -&gt; %2</source>
        <translation>bounds changed: %1 -&gt; %2</translation>
    </message>
    <message>
        <source>lock changed: %1 -&gt; %2</source>
        <translation>lock changed: %1 -&gt; %2</translation>
    </message>
    <message>
        <source>fit-error threshold changed: %1 -&gt; %2</source>
        <translation>fit-error threshold changed: %1 -&gt; %2</translation>
    </message>
    <message>
        <source>updating policy changed: %1 -&gt; %2</source>
        <translation>updating policy changed: %1 -&gt; %2</translation>
    </message>
    <message>
        <source>%1 (wall time %2)</source>
        <translation>%1 (wall time %2)</translation>
    </message>
    <message>
        <source>pre-flight check skipped: the test was started from the command line (--start)</source>
        <translation>pre-flight check skipped: the test was started from the command line (--start)</translation>
    </message>
    <message>
        <source>note recorded: %1</source>
        <translation>note recorded: %1</translation>
    </message>
    <message>
        <source>%1 (%L2 committed steps, last deformation %3 %4)</source>
        <translation>%1 (%L2 committed steps, last deformation %3 %4)</translation>
    </message>
    <message>
        <source>specimen loaded by an earlier test: %1; the operator continues on it</source>
        <translation>specimen loaded by an earlier test: %1; the operator continues on it</translation>
    </message>
    <message>
        <source>specimen loaded by an earlier test: %1; the operator chose a fresh specimen, its controller reset it to step 0</source>
        <translation>specimen loaded by an earlier test: %1; the operator chose a fresh specimen, its controller reset it to step 0</translation>
    </message>
    <message>
        <source>specimen loaded by an earlier test: %1; the operator chose a fresh specimen, its controller refused (nothing changed)</source>
        <translation>specimen loaded by an earlier test: %1; the operator chose a fresh specimen, its controller refused (nothing changed)</translation>
    </message>
</context>
<context>
    <name>OverrideOptions</name>
    <message>
        <source>The record's own sample step [s] (a one-column file of values needs it).</source>
        <translation>The record's own sample step [s] (a one-column file of values needs it).</translation>
    </message>
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
    <name>PlotExporter</name>
    <message>
        <source>%1: unknown plot format '%2' (expected png, svg or pdf)</source>
        <translation>%1: unknown plot format '%2' (expected png, svg or pdf)</translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation>%1: the plot could not be written</translation>
    </message>
</context>
<context>
    <name>PreflightChecks</name>
    <message>
        <source>time step dt [s]</source>
        <translation>time step dt [s]</translation>
    </message>
    <message>
        <source>duration [s]</source>
        <translation>duration [s]</translation>
    </message>
    <message>
        <source>ground motion</source>
        <translation>ground motion</translation>
    </message>
    <message>
        <source>ground motion scale [-]</source>
        <translation>ground motion scale [-]</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>integrator</translation>
    </message>
    <message>
        <source>controller</source>
        <translation>controller</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>steps</translation>
    </message>
    <message>
        <source>PGA [m/s²]</source>
        <translation>PGA [m/s²]</translation>
    </message>
    <message>
        <source>Unusual step count: %L1 steps (more than %L2); check dt and the duration.</source>
        <translation>Unusual step count: %L1 steps (more than %L2); check dt and the duration.</translation>
    </message>
    <message>
        <source>Unusual PGA: %1 m/s² (above %2 m/s²); check the ground motion scale.</source>
        <translation>Unusual PGA: %1 m/s² (above %2 m/s²); check the ground motion scale.</translation>
    </message>
    <message>
        <source>The ground motion is zero (PGA 0 m/s²).</source>
        <translation>The ground motion is zero (PGA 0 m/s²).</translation>
    </message>
    <message>
        <source>Very small time step: dt = %1 s.</source>
        <translation>Very small time step: dt = %1 s.</translation>
    </message>
    <message>
        <source>Changed since the last run: %1 %2 -&gt; %3</source>
        <translation>Changed since the last run: %1 %2 -&gt; %3</translation>
    </message>
</context>
<context>
    <name>PreflightDialog</name>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
</context>
<context>
    <name>ReplayCommand</name>
    <message>
        <source>Re-identify a recorded specimen, or imported measured data, offline.</source>
        <translation>Re-identify a recorded specimen, or imported measured data, offline.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>The subcommand.</translation>
    </message>
    <message>
        <source>A run record (record.h5).</source>
        <translation>A run record (record.h5).</translation>
    </message>
    <message>
        <source>Re-run the identification headless.</source>
        <translation>Re-run the identification headless.</translation>
    </message>
    <message>
        <source>JSON with "model" and/or "updating" settings to override.</source>
        <translation>JSON with "model" and/or "updating" settings to override.</translation>
    </message>
    <message>
        <source>The recorded specimen to identify.</source>
        <translation>The recorded specimen to identify.</translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation>Output directory.</translation>
    </message>
    <message>
        <source>unexpected argument '%1'</source>
        <translation>unexpected argument '%1'</translation>
    </message>
    <message>
        <source>give either FILE.h5 or --import DATA.csv, not both</source>
        <translation>give either FILE.h5 or --import DATA.csv, not both</translation>
    </message>
    <message>
        <source>expected FILE.h5 (a run record) or --import DATA.csv</source>
        <translation>expected FILE.h5 (a run record) or --import DATA.csv</translation>
    </message>
    <message>
        <source>--units applies to --import only (a record has its units)</source>
        <translation>--units applies to --import only (a record has its units)</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>missing --out DIR</translation>
    </message>
    <message>
        <source>%1 identification of %2: %3 samples, dt %4 s</source>
        <translation>%1 identification of %2: %3 samples, dt %4 s</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>parameter</translation>
    </message>
    <message>
        <source>initial</source>
        <translation>initial</translation>
    </message>
    <message>
        <source>final</source>
        <translation>final</translation>
    </message>
    <message>
        <source>std</source>
        <translation>std</translation>
    </message>
    <message>
        <source>online</source>
        <translation>online</translation>
    </message>
    <message>
        <source>  Nelder-Mead fits accepted: %1</source>
        <translation>  Nelder-Mead fits accepted: %1</translation>
    </message>
    <message>
        <source>  estimator warnings: %1 (see summary.json)</source>
        <translation>  estimator warnings: %1 (see summary.json)</translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation>  outputs: %1</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1: cannot create the output directory</translation>
    </message>
    <message>
        <source>Measured data: CSV or text of time (or a sample index), deformation, force with units.</source>
        <translation>Measured data: CSV or text of time (or a sample index), deformation, force with units.</translation>
    </message>
    <message>
        <source>Units of the imported columns time,deformation,force, e.g. s,mm,kN (time: s, ms or step; deformation: m, cm, mm, in, ft, rad, mrad, deg; force: N, kN, MN, lbf, kip, kgf, tonf, g or a moment such as kN*m, kip*in).</source>
        <translation>Units of the imported columns time,deformation,force, e.g. s,mm,kN (time: s, ms or step; deformation: m, cm, mm, in, ft, rad, mrad, deg; force: N, kN, MN, lbf, kip, kgf, tonf, g or a moment such as kN*m, kip*in).</translation>
    </message>
    <message>
        <source>Positions (from 1) of the imported time, deformation and force columns, e.g. 1,2,3; other columns are ignored.</source>
        <translation>Positions (from 1) of the imported time, deformation and force columns, e.g. 1,2,3; other columns are ignored.</translation>
    </message>
    <message>
        <source>--columns applies to --import only</source>
        <translation>--columns applies to --import only</translation>
    </message>
    <message>
        <source>  calibration over the whole history (%1 starts, %2 s): NRMSE %3 %</source>
        <translation>  calibration over the whole history (%1 starts, %2 s): NRMSE %3 %</translation>
    </message>
    <message>
        <source>on its bound</source>
        <translation>on its bound</translation>
    </message>
    <message>
        <source>  verdict: %1</source>
        <translation>  verdict: %1</translation>
    </message>
    <message>
        <source>uRef %1 %2, fRef %3 %4</source>
        <translation>uRef %1 %2, fRef %3 %4</translation>
    </message>
    <message>
        <source>  normalized units (x = u / uRef, f = F / fRef), final model's scales: %1</source>
        <translation>  normalized units (x = u / uRef, f = F / fRef), final model's scales: %1</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>unit</translation>
    </message>
    <message>
        <source>  final model over the whole history: RMS force error %1 %2 (NRMSE %3 %; the initial model's %4 %)</source>
        <translation>  final model over the whole history: RMS force error %1 %2 (NRMSE %3 %; the initial model's %4 %)</translation>
    </message>
    <message>
        <source>  online model's prediction over the record (each sample with the estimate known before it): NRMSE %1 %</source>
        <translation>  online model's prediction over the record (each sample with the estimate known before it): NRMSE %1 %</translation>
    </message>
    <message>
        <source>  warning: %1</source>
        <translation>  warning: %1</translation>
    </message>
    <message>
        <source>    in the same scales: %1</source>
        <translation>    in the same scales: %1</translation>
    </message>
    <message>
        <source>    in its own scales: %1 (its normalized values are not comparable with the table's above)</source>
        <translation>    in its own scales: %1 (its normalized values are not comparable with the table's above)</translation>
    </message>
    <message>
        <source>The calibration's deformation and force offsets: auto (fitted when the data ask for them, the default), on or off.</source>
        <translation>The calibration's deformation and force offsets: auto (fitted when the data ask for them, the default), on or off.</translation>
    </message>
    <message>
        <source>--offsets: expected auto, on or off, found '%1'</source>
        <translation>--offsets: expected auto, on or off, found '%1'</translation>
    </message>
    <message>
        <source>    offsets fitted: NRMSE %1 % with them, %2 % without (criterion %3 &lt; 0 over %4 branches)</source>
        <translation>    offsets fitted: NRMSE %1 % with them, %2 % without (criterion %3 &lt; 0 over %4 branches)</translation>
    </message>
    <message>
        <source>    offsets not needed: NRMSE %1 % with them, %2 % without (criterion %3 &gt;= 0 over %4 branches)</source>
        <translation>    offsets not needed: NRMSE %1 % with them, %2 % without (criterion %3 &gt;= 0 over %4 branches)</translation>
    </message>
    <message>
        <source>hsmu replay: %1 / %2 samples, %3 refits, %4 rejected, %5 s elapsed, about %6 s left</source>
        <translation>hsmu replay: %1 / %2 samples, %3 refits, %4 rejected, %5 s elapsed, about %6 s left</translation>
    </message>
    <message>
        <source>hsmu replay: %1 (%2 s elapsed)</source>
        <translation>hsmu replay: %1 (%2 s elapsed)</translation>
    </message>
    <message>
        <source>calibrating over the whole history</source>
        <translation>calibrating over the whole history</translation>
    </message>
    <message>
        <source>final fit over the whole history</source>
        <translation>final fit over the whole history</translation>
    </message>
    <message>
        <source>ukf, nelder-mead, calibration (only the whole-history fit) or all (the three, compared in one table).</source>
        <translation>ukf, nelder-mead, calibration (only the whole-history fit) or all (the three, compared in one table).</translation>
    </message>
    <message>
        <source>hsmu replay: calibrating over the whole history (minimization %1 of %2, %3 s elapsed)</source>
        <translation>hsmu replay: calibrating over the whole history (minimization %1 of %2, %3 s elapsed)</translation>
    </message>
    <message>
        <source>%1 identification of %2 interrupted (%3) during the %4: %5 / %6 samples done, %7 refits, %8 rejected</source>
        <translation>%1 identification of %2 interrupted (%3) during the %4: %5 / %6 samples done, %7 refits, %8 rejected</translation>
    </message>
    <message>
        <source>online pass</source>
        <translation>online pass</translation>
    </message>
    <message>
        <source>calibration</source>
        <translation>calibration</translation>
    </message>
    <message>
        <source>final fit</source>
        <translation>final fit</translation>
    </message>
    <message>
        <source>  no estimate yet</source>
        <translation>  no estimate yet</translation>
    </message>
    <message>
        <source>  parameters after sample %1:</source>
        <translation>  parameters after sample %1:</translation>
    </message>
    <message>
        <source>  partial summary: %1</source>
        <translation>  partial summary: %1</translation>
    </message>
</context>
<context>
    <name>ReplayExport</name>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: cannot be written (%2)</translation>
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
        <translation>Replay a recorded test (an HDF5 run record) in a window.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>The subcommand.</translation>
    </message>
    <message>
        <source>The run record (record.h5).</source>
        <translation>The run record (record.h5).</translation>
    </message>
    <message>
        <source>Test seconds per wall second (default 1).</source>
        <translation>Test seconds per wall second (default 1).</translation>
    </message>
    <message>
        <source>Start playing at once.</source>
        <translation>Start playing at once.</translation>
    </message>
    <message>
        <source>Grab the window into this PNG file, then quit.</source>
        <translation>Grab the window into this PNG file, then quit.</translation>
    </message>
    <message>
        <source>Seconds before the screenshot (default 3).</source>
        <translation>Seconds before the screenshot (default 3).</translation>
    </message>
    <message>
        <source>expected one record file: hsmu replay FILE.h5</source>
        <translation>expected one record file: hsmu replay FILE.h5</translation>
    </message>
    <message>
        <source>--speed: expected a positive number</source>
        <translation>--speed: expected a positive number</translation>
    </message>
    <message>
        <source>--screenshot-after: expected a number of seconds</source>
        <translation>--screenshot-after: expected a number of seconds</translation>
    </message>
</context>
<context>
    <name>RthsCommand</name>
    <message>
        <source>the controller did not resume the run: %1</source>
        <translation>the controller did not resume the run: %1</translation>
    </message>
    <message>
        <source>With --controller: resume the controller&apos;s held run from the tick where it held instead of starting one.</source>
        <translation>With --controller: resume the controller&apos;s held run from the tick where it held instead of starting one.</translation>
    </message>
    <message>
        <source>--resume needs --controller: it resumes the held run hsmu-controller keeps (a local run is resumed in the console&apos;s RTHS view)</source>
        <translation>--resume needs --controller: it resumes the held run hsmu-controller keeps (a local run is resumed in the console&apos;s RTHS view)</translation>
    </message>
    <message>
        <source>Real-time hybrid simulation on the virtual lab's servo-hydraulic actuator.</source>
        <translation>Real-time hybrid simulation on the virtual lab's servo-hydraulic actuator.</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>The subcommand.</translation>
    </message>
    <message>
        <source>A configuration file or rths-benchmark-case-1 .. -4.</source>
        <translation>A configuration file or rths-benchmark-case-1 .. -4.</translation>
    </message>
    <message>
        <source>Output folder.</source>
        <translation>Output folder.</translation>
    </message>
    <message>
        <source>Ground-motion record (m/s^2 unless the configuration says).</source>
        <translation>Ground-motion record (m/s^2 unless the configuration says).</translation>
    </message>
    <message>
        <source>Scale of the record.</source>
        <translation>Scale of the record.</translation>
    </message>
    <message>
        <source>Stop after T seconds.</source>
        <translation>Stop after T seconds.</translation>
    </message>
    <message>
        <source>fast (simulated, default) or realtime (wall clock).</source>
        <translation>fast (simulated, default) or realtime (wall clock).</translation>
    </message>
    <message>
        <source>Run the loop's thread under SCHED_FIFO (with --pace realtime).</source>
        <translation>Run the loop's thread under SCHED_FIFO (with --pace realtime).</translation>
    </message>
    <message>
        <source>default, none, lead, polynomial, feedforward or ats.</source>
        <translation>default, none, lead, polynomial, feedforward or ats.</translation>
    </message>
    <message>
        <source>Draw the plant from the benchmark's distributions with this seed.</source>
        <translation>Draw the plant from the benchmark's distributions with this seed.</translation>
    </message>
    <message>
        <source>With --pace realtime: busy-wait the last N microseconds before each release (default: a quarter of the period, at most 100; 0: sleep only).</source>
        <translation>With --pace realtime: busy-wait the last N microseconds before each release (default: a quarter of the period, at most 100; 0: sleep only).</translation>
    </message>
    <message>
        <source>--spin-us: expected 0 up to the loop period (%1 us), got &apos;%2&apos;</source>
        <translation>--spin-us: expected 0 up to the loop period (%1 us), got &apos;%2&apos;</translation>
    </message>
    <message>
        <source>Check this computer instead of running: release S seconds of empty ticks at the configuration&apos;s loop rate (with --realtime-priority and --spin-us as a run would) and report how late they come.</source>
        <translation>Check this computer instead of running: release S seconds of empty ticks at the configuration&apos;s loop rate (with --realtime-priority and --spin-us as a run would) and report how late they come.</translation>
    </message>
    <message>
        <source>--probe-host checks this computer: run it on the controller&apos;s computer without --controller</source>
        <translation>--probe-host checks this computer: run it on the controller&apos;s computer without --controller</translation>
    </message>
    <message>
        <source>--probe-host: expected seconds in (0, 3600], got &apos;%1&apos;</source>
        <translation>--probe-host: expected seconds in (0, 3600], got &apos;%1&apos;</translation>
    </message>
    <message>
        <source>hsmu rths: real-time priority not taken (%1); the probe ran at normal priority</source>
        <translation>hsmu rths: real-time priority not taken (%1); the probe ran at normal priority</translation>
    </message>
    <message>
        <source>host probe at %1 Hz (spin %2 us%3): %4</source>
        <translation>host probe at %1 Hz (spin %2 us%3): %4</translation>
    </message>
    <message>
        <source>, SCHED_FIFO 80</source>
        <translation>, SCHED_FIFO 80</translation>
    </message>
    <message>
        <source>Sensor noise seed.</source>
        <translation>Sensor noise seed.</translation>
    </message>
    <message>
        <source>Sensors without noise.</source>
        <translation>Sensors without noise.</translation>
    </message>
    <message>
        <source>expected one CONFIG (a file or rths-benchmark-case-1 .. -4)</source>
        <translation>expected one CONFIG (a file or rths-benchmark-case-1 .. -4)</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>missing --out DIR</translation>
    </message>
    <message>
        <source>--pace: expected fast or realtime, got '%1'</source>
        <translation>--pace: expected fast or realtime, got '%1'</translation>
    </message>
    <message>
        <source>--compensation: expected default, none, lead, polynomial, feedforward or ats, got '%1'</source>
        <translation>--compensation: expected default, none, lead, polynomial, feedforward or ats, got '%1'</translation>
    </message>
    <message>
        <source>--seed, --scale and --duration take numbers</source>
        <translation>--seed, --scale and --duration take numbers</translation>
    </message>
    <message>
        <source>--perturb takes a seed</source>
        <translation>--perturb takes a seed</translation>
    </message>
    <message>
        <source>no ground motion: give --ground-motion FILE</source>
        <translation>no ground motion: give --ground-motion FILE</translation>
    </message>
    <message>
        <source>%1: the ground-motion record does not exist (give --ground-motion FILE)</source>
        <translation>%1: the ground-motion record does not exist (give --ground-motion FILE)</translation>
    </message>
    <message>
        <source>%1: %2 Hz loop, compensation %3%4</source>
        <translation>%1: %2 Hz loop, compensation %3%4</translation>
    </message>
    <message>
        <source> + phase lead</source>
        <translation> + phase lead</translation>
    </message>
    <message>
        <source>pre-flight: %1</source>
        <translation>pre-flight: %1</translation>
    </message>
    <message>
        <source>refused in pre-flight: %1</source>
        <translation>refused in pre-flight: %1</translation>
    </message>
    <message>
        <source>%1: cannot create the output folder</source>
        <translation>%1: cannot create the output folder</translation>
    </message>
    <message>
        <source>hsmu rths: real-time priority not taken (%1); the loop ran at normal priority</source>
        <translation>hsmu rths: real-time priority not taken (%1); the loop ran at normal priority</translation>
    </message>
    <message>
        <source>%1 ticks (%2 s); %3</source>
        <translation>%1 ticks (%2 s); %3</translation>
    </message>
    <message>
        <source>frequency evaluation: amplitude %1, delay %2 ms at %3 Hz; tracking indicator %4 m^2</source>
        <translation>frequency evaluation: amplitude %1, delay %2 ms at %3 Hz; tracking indicator %4 m^2</translation>
    </message>
    <message>
        <source>deadline misses: %1 (worst %2 us late)</source>
        <translation>deadline misses: %1 (worst %2 us late)</translation>
    </message>
    <message>
        <source>outputs: %1/record.h5, %1/steps.csv, %1/summary.json</source>
        <translation>outputs: %1/record.h5, %1/steps.csv, %1/summary.json</translation>
    </message>
    <message>
        <source>hsmu rths: %1</source>
        <translation>hsmu rths: %1</translation>
    </message>
    <message>
        <source>Monitor the loop run by hsmu-controller --rths at tcp://HOST:PORT.</source>
        <translation>Monitor the loop run by hsmu-controller --rths at tcp://HOST:PORT.</translation>
    </message>
    <message>
        <source>File whose first line is the controller's shared secret.</source>
        <translation>File whose first line is the controller's shared secret.</translation>
    </message>
    <message>
        <source>With --controller: one telemetry frame every N ticks (default: about 128 per second).</source>
        <translation>With --controller: one telemetry frame every N ticks (default: about 128 per second).</translation>
    </message>
    <message>
        <source>--%1 does not apply with --controller: the controller runs the loop of its own copy of the configuration</source>
        <translation>--%1 does not apply with --controller: the controller runs the loop of its own copy of the configuration</translation>
    </message>
    <message>
        <source>--controller: %1</source>
        <translation>--controller: %1</translation>
    </message>
    <message>
        <source>--controller: an RTHS loop is monitored over tcp://HOST:PORT (hsmu-controller --rths)</source>
        <translation>--controller: an RTHS loop is monitored over tcp://HOST:PORT (hsmu-controller --rths)</translation>
    </message>
    <message>
        <source>--token-file: %1</source>
        <translation>--token-file: %1</translation>
    </message>
    <message>
        <source>--telemetry-every: expected a whole number &gt;= 1, got '%1'</source>
        <translation>--telemetry-every: expected a whole number &gt;= 1, got '%1'</translation>
    </message>
    <message>
        <source>With --controller: at T seconds of the run, send new values of the damper twin's parameters (repeatable).</source>
        <translation>With --controller: at T seconds of the run, send new values of the damper twin's parameters (repeatable).</translation>
    </message>
    <message>
        <source>--update: expected T:NAME=VALUE[,NAME=VALUE...] (seconds, then the damper twin's parameters), got '%1'</source>
        <translation>--update: expected T:NAME=VALUE[,NAME=VALUE...] (seconds, then the damper twin's parameters), got '%1'</translation>
    </message>
    <message>
        <source>--update needs --controller: it sends the update to the loop hsmu-controller runs</source>
        <translation>--update needs --controller: it sends the update to the loop hsmu-controller runs</translation>
    </message>
    <message>
        <source>%1/telemetry.csv: cannot be written</source>
        <translation>%1/telemetry.csv: cannot be written</translation>
    </message>
    <message>
        <source>cannot reach the controller %1:%2: %3</source>
        <translation>cannot reach the controller %1:%2: %3</translation>
    </message>
    <message>
        <source>the controller refused the monitor: %1</source>
        <translation>the controller refused the monitor: %1</translation>
    </message>
    <message>
        <source>controller: %1</source>
        <translation>controller: %1</translation>
    </message>
    <message>
        <source>the link to the controller was lost: %1 (the controller holds the loop per its --monitor-loss policy); %2 telemetry frames in %3/telemetry.csv</source>
        <translation>the link to the controller was lost: %1 (the controller holds the loop per its --monitor-loss policy); %2 telemetry frames in %3/telemetry.csv</translation>
    </message>
    <message>
        <source>t = %1 s: desired %2 mm, measured %3 mm, %4 deadline misses</source>
        <translation>t = %1 s: desired %2 mm, measured %3 mm, %4 deadline misses</translation>
    </message>
    <message>
        <source>the controller: %1</source>
        <translation>the controller: %1</translation>
    </message>
    <message>
        <source>%1 ticks on the controller; %2</source>
        <translation>%1 ticks on the controller; %2</translation>
    </message>
    <message>
        <source>deadline misses: %1 (worst %2 us late); telemetry %3 received, %4 dropped</source>
        <translation>deadline misses: %1 (worst %2 us late); telemetry %3 received, %4 dropped</translation>
    </message>
    <message>
        <source>outputs: %1/telemetry.csv, %1/summary.json</source>
        <translation>outputs: %1/telemetry.csv, %1/summary.json</translation>
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
        <source>hsmu run: --approval ignored: the configuration has no updating</source>
        <translation>hsmu run: --approval ignored: the configuration has no updating</translation>
    </message>
    <message>
        <source>hsmu run: connecting to %1 (%2 protocol, %3)</source>
        <translation>hsmu run: connecting to %1 (%2 protocol, %3)</translation>
    </message>
    <message>
        <source>hsmu run: steps.csv not written (%1 columns); record.h5 holds every column (hsmu export writes CSV from it)</source>
        <translation>hsmu run: steps.csv not written (%1 columns); record.h5 holds every column (hsmu export writes CSV from it)</translation>
    </message>
    <message>
        <source>hsmu run: link fault at t = %1 s (step %2): %3; reconnecting in %4 s (attempt %5 of %6)</source>
        <translation>hsmu run: link fault at t = %1 s (step %2): %3; reconnecting in %4 s (attempt %5 of %6)</translation>
    </message>
    <message>
        <source>--plots: this program cannot draw (run it through hsmu)</source>
        <translation>--plots: this program cannot draw (run it through hsmu)</translation>
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
        <source>File whose first line is the controller's shared secret (readable by you only; else the environment variable HSMU_CONTROLLER_TOKEN).</source>
        <translation>File whose first line is the controller's shared secret (readable by you only; else the environment variable HSMU_CONTROLLER_TOKEN).</translation>
    </message>
    <message>
        <source>--token is not accepted: arguments show in ps; put the token in a file (--token-file FILE) or in the environment variable HSMU_CONTROLLER_TOKEN</source>
        <translation>--token is not accepted: arguments show in ps; put the token in a file (--token-file FILE) or in the environment variable HSMU_CONTROLLER_TOKEN</translation>
    </message>
    <message>
        <source>--token-file: %1</source>
        <translation>--token-file: %1</translation>
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
    <message>
        <source>Actuator controller: builtin (in-process virtual specimens, the default), tcp://HOST:PORT (hsmu-controller or a lab controller, in the configuration's controller.protocol, native by default), simapp://HOST:PORT (an OpenFresco SimApp server) or generictcp://HOST:PORT (a server for OpenFresco's GenericTCP).</source>
        <translation>Actuator controller: builtin (in-process virtual specimens, the default), tcp://HOST:PORT (hsmu-controller or a lab controller, in the configuration's controller.protocol, native by default), simapp://HOST:PORT (an OpenFresco SimApp server) or generictcp://HOST:PORT (a server for OpenFresco's GenericTCP).</translation>
    </message>
    <message>
        <source>steps.csv: auto (written when a row has at most 200 values, the default), all or none; record.h5 holds every column either way.</source>
        <translation>steps.csv: auto (written when a row has at most 200 values, the default), all or none; record.h5 holds every column either way.</translation>
    </message>
    <message>
        <source>Compress the record's per-step matrices: deflate level 1-9 with shuffle (default 0: uncompressed).</source>
        <translation>Compress the record's per-step matrices: deflate level 1-9 with shuffle (default 0: uncompressed).</translation>
    </message>
    <message>
        <source>--csv: expected auto, all or none, found '%1'</source>
        <translation>--csv: expected auto, all or none, found '%1'</translation>
    </message>
    <message>
        <source>--compress: expected a whole number from 0 to 9, found '%1'</source>
        <translation>--compress: expected a whole number from 0 to 9, found '%1'</translation>
    </message>
    <message>
        <source>Numerical DOFs the record keeps: indices, ranges and names, e.g. 0-9,100,Roof (default: every DOF). A specimen's channels are always recorded in full.</source>
        <translation>Numerical DOFs the record keeps: indices, ranges and names, e.g. 0-9,100,Roof (default: every DOF). A specimen's channels are always recorded in full.</translation>
    </message>
    <message>
        <source>Keep the numerical DOFs' rows of every N-th step only (default 1). A specimen's channels are always recorded at every step.</source>
        <translation>Keep the numerical DOFs' rows of every N-th step only (default 1). A specimen's channels are always recorded at every step.</translation>
    </message>
    <message>
        <source>--record-every: expected a whole number from 1 to %1, found '%2'</source>
        <translation>--record-every: expected a whole number from 1 to %1, found '%2'</translation>
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
        <source>  tracking of %1 (commanded against measured): J1 %2 ms, J2 %3 %, J3 %4 %</source>
        <translation>  tracking of %1 (commanded against measured): J1 %2 ms, J2 %3 %, J3 %4 %</translation>
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
    <message>
        <source>  record: DOFs %1 (%2 of %3), every %4 steps; elements, specimens and updating at every step</source>
        <translation>  record: DOFs %1 (%2 of %3), every %4 steps; elements, specimens and updating at every step</translation>
    </message>
    <message>
        <source>... %1 more in summary.json</source>
        <translation>... %1 more in summary.json</translation>
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
    <name>hsmu::gui::ActuatorsPanel</name>
    <message>
        <source>Displacement [%1]</source>
        <translation>Displacement [%1]</translation>
    </message>
    <message>
        <source>Rotation [%1]</source>
        <translation>Rotation [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation>Force [%1]</translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation>Moment [%1]</translation>
    </message>
    <message>
        <source>axial</source>
        <translation>axial</translation>
    </message>
    <message>
        <source>shear</source>
        <translation>shear</translation>
    </message>
    <message>
        <source>rotation</source>
        <translation>rotation</translation>
    </message>
    <message>
        <source>commanded</source>
        <translation>commanded</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>measured</translation>
    </message>
    <message>
        <source>command</source>
        <translation>command</translation>
    </message>
    <message>
        <source>stroke</source>
        <translation>stroke</translation>
    </message>
    <message>
        <source>force</source>
        <translation>force</translation>
    </message>
    <message>
        <source>%1: %2 DOF</source>
        <translation>%1: %2 DOF</translation>
    </message>
    <message>
        <source>%1: actuator &apos;%2&apos;</source>
        <translation>%1: actuator &apos;%2&apos;</translation>
    </message>
    <message>
        <source>%1: every basic deformation</source>
        <translation>%1: every basic deformation</translation>
    </message>
    <message>
        <source>%1: every basic force</source>
        <translation>%1: every basic force</translation>
    </message>
    <message>
        <source>%1: every actuator&apos;s stroke</source>
        <translation>%1: every actuator&apos;s stroke</translation>
    </message>
    <message>
        <source>%1: every actuator&apos;s force</source>
        <translation>%1: every actuator&apos;s force</translation>
    </message>
    <message>
        <source>The actuator, basic DOF or set of channels the plot shows</source>
        <translation>The actuator, basic DOF or set of channels the plot shows</translation>
    </message>
    <message>
        <source>No step yet.</source>
        <translation>No step yet.</translation>
    </message>
    <message>
        <source>Step %1, t = %2 s: %3</source>
        <translation>Step %1, t = %2 s: %3</translation>
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
    <message>
        <source>Time [s]</source>
        <translation>Time [s]</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Step</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Severity</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Kind</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>Acknowledged</source>
        <translation>Acknowledged</translation>
    </message>
    <message>
        <source>console</source>
        <translation>console</translation>
    </message>
    <message>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <source>yes, %1</source>
        <translation>yes, %1</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: cannot be written (%2)</translation>
    </message>
    <message>
        <source>Copy the list</source>
        <translation>Copy the list</translation>
    </message>
    <message>
        <source>Copy selected rows</source>
        <translation>Copy selected rows</translation>
    </message>
    <message>
        <source>Export the list as CSV...</source>
        <translation>Export the list as CSV...</translation>
    </message>
    <message>
        <source>Export alarms and events</source>
        <translation>Export alarms and events</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV files (*.csv)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::AlarmPanel</name>
    <message>
        <source>Acknowledge selected</source>
        <translation>Acknowledge selected</translation>
    </message>
    <message>
        <source>Acknowledge all</source>
        <translation>Acknowledge all</translation>
    </message>
    <message>
        <source>Critical alarms stay red until acknowledged (double-click or the buttons).</source>
        <translation>Critical alarms stay red until acknowledged (double-click or the buttons).</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::AttentionBanner</name>
    <message>
        <source>Acknowledge all</source>
        <translation>Acknowledge all</translation>
    </message>
    <message numerus="yes">
        <source>%n critical alarm(s) not acknowledged. Latest: %1</source>
        <translation>
            <numerusform>%n critical alarm(s) not acknowledged. Latest: %1</numerusform>
            <numerusform>%n critical alarm(s) not acknowledged. Latest: %1</numerusform>
        </translation>
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
    <message>
        <source>Single step</source>
        <translation>Single step</translation>
    </message>
    <message>
        <source>Emergency hold (%1)</source>
        <translation>Emergency hold (%1)</translation>
    </message>
    <message>
        <source>Hold the test at once, between two steps (%1)</source>
        <translation>Hold the test at once, between two steps (%1)</translation>
    </message>
    <message>
        <source>Stop...</source>
        <translation>Stop...</translation>
    </message>
    <message>
        <source>1/%1 x real time</source>
        <translation>1/%1 x real time</translation>
    </message>
    <message>
        <source>fixed wall time per step</source>
        <translation>fixed wall time per step</translation>
    </message>
    <message>
        <source>Each step takes this long in wall time (pseudo-dynamic pace)</source>
        <translation>Each step takes this long in wall time (pseudo-dynamic pace)</translation>
    </message>
    <message>
        <source> s/step</source>
        <translation> s/step</translation>
    </message>
    <message>
        <source>Start the test after the pre-flight check (%1)</source>
        <translation>Start the test after the pre-flight check (%1)</translation>
    </message>
    <message>
        <source>Pause between two steps (%1)</source>
        <translation>Pause between two steps (%1)</translation>
    </message>
    <message>
        <source>Run exactly one integration step, then stay paused (%1)</source>
        <translation>Run exactly one integration step, then stay paused (%1)</translation>
    </message>
    <message>
        <source>Continue the test (%1)</source>
        <translation>Continue the test (%1)</translation>
    </message>
    <message>
        <source>End the test, keeping the data (asks for confirmation; %1)</source>
        <translation>End the test, keeping the data (asks for confirmation; %1)</translation>
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
    <message>
        <source>Force history</source>
        <translation>Force history</translation>
    </message>
    <message>
        <source>Moment history</source>
        <translation>Moment history</translation>
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
        <source>Tracking of %1</source>
        <translation>Tracking of %1</translation>
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
        <source>commanded</source>
        <translation>commanded</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>measured</translation>
    </message>
    <message>
        <source>Inspector fit error</source>
        <translation>Inspector fit error</translation>
    </message>
    <message>
        <source>Fit error [-]</source>
        <translation>Fit error [-]</translation>
    </message>
    <message>
        <source>fit error</source>
        <translation>fit error</translation>
    </message>
    <message>
        <source>actuator command</source>
        <translation>actuator command</translation>
    </message>
    <message>
        <source>held ticks</source>
        <translation>held ticks</translation>
    </message>
    <message>
        <source>Held ticks [-]</source>
        <translation>Held ticks [-]</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::HysteresisPlot</name>
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
        <source>auxiliary model (%1)</source>
        <translation>auxiliary model (%1)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::LivePlotsPanel</name>
    <message>
        <source>Dashed: %1</source>
        <translation>Dashed: %1</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG image (*.png)</translation>
    </message>
    <message>
        <source>SVG drawing (*.svg)</source>
        <translation>SVG drawing (*.svg)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF document (*.pdf)</translation>
    </message>
    <message>
        <source>Export this plot...</source>
        <translation>Export this plot...</translation>
    </message>
    <message>
        <source>Export all plots...</source>
        <translation>Export all plots...</translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation>Export plot</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Export failed</translation>
    </message>
    <message>
        <source>Export all plots to</source>
        <translation>Export all plots to</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::MainWindow</name>
    <message>
        <source>Enter the record's sample step below the file.</source>
        <translation>Enter the record's sample step below the file.</translation>
    </message>
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
    <message>
        <source>Test setup</source>
        <translation>Test setup</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameters</translation>
    </message>
    <message>
        <source>Pending updates</source>
        <translation>Pending updates</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>&amp;Open configuration...</source>
        <translation>&amp;Open configuration...</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>Open &amp;recent</translation>
    </message>
    <message>
        <source>Open r&amp;ecord...</source>
        <translation>Open r&amp;ecord...</translation>
    </message>
    <message>
        <source>&amp;Settings...</source>
        <translation>&amp;Settings...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(none)</translation>
    </message>
    <message>
        <source>setup not applied: %1</source>
        <translation>setup not applied: %1</translation>
    </message>
    <message>
        <source>preparing the test (pre-flight)...</source>
        <translation>preparing the test (pre-flight)...</translation>
    </message>
    <message>
        <source>start cancelled at the pre-flight check</source>
        <translation>start cancelled at the pre-flight check</translation>
    </message>
    <message>
        <source>Add &amp;note...</source>
        <translation>Add &amp;note...</translation>
    </message>
    <message>
        <source>Record a note at the current step of the test</source>
        <translation>Record a note at the current step of the test</translation>
    </message>
    <message>
        <source>Add note</source>
        <translation>Add note</translation>
    </message>
    <message>
        <source>Load and start a test first.</source>
        <translation>Load and start a test first.</translation>
    </message>
    <message>
        <source>Note (recorded with the current step and test time):</source>
        <translation>Note (recorded with the current step and test time):</translation>
    </message>
    <message>
        <source>Quit the console (asks first while a test runs)</source>
        <translation>Quit the console (asks first while a test runs)</translation>
    </message>
    <message>
        <source>testing the link...</source>
        <translation>testing the link...</translation>
    </message>
    <message>
        <source>This ground motion cannot be used: %1</source>
        <translation>This ground motion cannot be used: %1</translation>
    </message>
    <message>
        <source>ground motion not usable: %1</source>
        <translation>ground motion not usable: %1</translation>
    </message>
    <message>
        <source>A test is running</source>
        <translation>A test is running</translation>
    </message>
    <message>
        <source>Continue the test</source>
        <translation>Continue the test</translation>
    </message>
    <message>
        <source>End the test now? The specimen is held, the test cannot be resumed, and every step so far stays in the record.</source>
        <translation>End the test now? The specimen is held, the test cannot be resumed, and every step so far stays in the record.</translation>
    </message>
    <message>
        <source>End the test and keep the data</source>
        <translation>End the test and keep the data</translation>
    </message>
    <message>
        <source>link tested: %1 answered; the test is prepared, Start shows the pre-flight check</source>
        <translation>link tested: %1 answered; the test is prepared, Start shows the pre-flight check</translation>
    </message>
    <message>
        <source>A test is running. Quit the console? The test is ended first: the specimen is held and every step so far stays in the record.</source>
        <translation>A test is running. Quit the console? The test is ended first: the specimen is held and every step so far stays in the record.</translation>
    </message>
    <message>
        <source>End the test, keep the data and quit</source>
        <translation>End the test, keep the data and quit</translation>
    </message>
    <message>
        <source>(dataSize %1; ctrl sizes %2; daq sizes %3)</source>
        <translation>(dataSize %1; ctrl sizes %2; daq sizes %3)</translation>
    </message>
    <message>
        <source>test finished: %1 steps, t = %2 s</source>
        <translation>test finished: %1 steps, t = %2 s</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <source>Console &amp;guide</source>
        <translation>Console &amp;guide</translation>
    </message>
    <message>
        <source>The console's documentation (docs/console.md)</source>
        <translation>The console's documentation (docs/console.md)</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>&amp;Keyboard shortcuts</translation>
    </message>
    <message>
        <source>&amp;About HSMU Console</source>
        <translation>&amp;About HSMU Console</translation>
    </message>
    <message>
        <source>%1: Start (after the pre-flight check)</source>
        <translation>%1: Start (after the pre-flight check)</translation>
    </message>
    <message>
        <source>%1: Pause</source>
        <translation>%1: Pause</translation>
    </message>
    <message>
        <source>%1: Resume</source>
        <translation>%1: Resume</translation>
    </message>
    <message>
        <source>%1: Single step</source>
        <translation>%1: Single step</translation>
    </message>
    <message>
        <source>%1: Stop (asks first)</source>
        <translation>%1: Stop (asks first)</translation>
    </message>
    <message>
        <source>%1: Emergency hold (every window, always)</source>
        <translation>%1: Emergency hold (every window, always)</translation>
    </message>
    <message>
        <source>%1: Add a note to the record</source>
        <translation>%1: Add a note to the record</translation>
    </message>
    <message>
        <source>%1: Open a configuration</source>
        <translation>%1: Open a configuration</translation>
    </message>
    <message>
        <source>%1: Copy the selected alarms and events</source>
        <translation>%1: Copy the selected alarms and events</translation>
    </message>
    <message>
        <source>%1: Console guide</source>
        <translation>%1: Console guide</translation>
    </message>
    <message>
        <source>%1: Quit (asks first while a test runs)</source>
        <translation>%1: Quit (asks first while a test runs)</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Keyboard shortcuts</translation>
    </message>
    <message>
        <source>About HSMU Console</source>
        <translation>About HSMU Console</translation>
    </message>
    <message>
        <source>HSMU Console %1
Hybrid simulation with online model updating (Hashemi, Masroor &amp; Mosqueda, EESD 2014).</source>
        <translation>HSMU Console %1
Hybrid simulation with online model updating (Hashemi, Masroor &amp; Mosqueda, EESD 2014).</translation>
    </message>
    <message>
        <source>Console guide</source>
        <translation>Console guide</translation>
    </message>
    <message>
        <source>The guide is docs/console.md of the source tree, installed as share/doc/hsmu/console.md.</source>
        <translation>The guide is docs/console.md of the source tree, installed as share/doc/hsmu/console.md.</translation>
    </message>
    <message>
        <source>asking the controller for a fresh specimen...</source>
        <translation>asking the controller for a fresh specimen...</translation>
    </message>
    <message>
        <source>Real-time hybrid simulation</source>
        <translation>Real-time hybrid simulation</translation>
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
    <name>hsmu::gui::ParameterTableModel</name>
    <message>
        <source>Double-click to edit; effective on the next step</source>
        <translation>Double-click to edit; effective on the next step</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <source>Sigma</source>
        <translation>Sigma</translation>
    </message>
    <message>
        <source>Lower</source>
        <translation>Lower</translation>
    </message>
    <message>
        <source>Upper</source>
        <translation>Upper</translation>
    </message>
    <message>
        <source>Lock</source>
        <translation>Lock</translation>
    </message>
    <message>
        <source>%1: '%2' is not a number</source>
        <translation>%1: '%2' is not a number</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ParametersPanel</name>
    <message>
        <source>No online model updating in this test.</source>
        <translation>No online model updating in this test.</translation>
    </message>
    <message>
        <source>Normalized RMS fit error above which the inspector requests an update; effective on the next step</source>
        <translation>Normalized RMS fit error above which the inspector requests an update; effective on the next step</translation>
    </message>
    <message>
        <source>Fit-error threshold [-]:</source>
        <translation>Fit-error threshold [-]:</translation>
    </message>
    <message>
        <source>Value, sigma (1 standard deviation) and bounds in the law's normalized units (u / u_ref, F / F_ref). Double-click a bound to edit it; bound and lock edits take effect on the next step.</source>
        <translation>Value, sigma (1 standard deviation) and bounds in the law's normalized units (u / u_ref, F / F_ref). Double-click a bound to edit it; bound and lock edits take effect on the next step.</translation>
    </message>
    <message>
        <source>%1 on %2 at step %3: fit error e = %4 (threshold %5), %6 updates applied</source>
        <translation>%1 on %2 at step %3: fit error e = %4 (threshold %5), %6 updates applied</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PendingUpdatesPanel</name>
    <message>
        <source>every step</source>
        <translation>every step</translation>
    </message>
    <message>
        <source>at zero-force crossings of the target</source>
        <translation>at zero-force crossings of the target</translation>
    </message>
    <message>
        <source>every N steps</source>
        <translation>every N steps</translation>
    </message>
    <message>
        <source>on the operator's approval</source>
        <translation>on the operator's approval</translation>
    </message>
    <message>
        <source>N = </source>
        <translation>N = </translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Current</translation>
    </message>
    <message>
        <source>Proposed</source>
        <translation>Proposed</translation>
    </message>
    <message>
        <source>Change [%]</source>
        <translation>Change [%]</translation>
    </message>
    <message>
        <source>Apply updates:</source>
        <translation>Apply updates:</translation>
    </message>
    <message>
        <source>No online model updating in this test.</source>
        <translation>No online model updating in this test.</translation>
    </message>
    <message>
        <source>Updates are applied %1; choose "on the operator's approval" to decide each one.</source>
        <translation>Updates are applied %1; choose "on the operator's approval" to decide each one.</translation>
    </message>
    <message>
        <source>#%1 %2 at t = %3 s (step %4)</source>
        <translation>#%1 %2 at t = %3 s (step %4)</translation>
    </message>
    <message>
        <source>Approve</source>
        <translation>Approve</translation>
    </message>
    <message>
        <source>Reject</source>
        <translation>Reject</translation>
    </message>
    <message numerus="yes">
        <source>%n newer proposal(s) were not queued (the queue holds %1); each is in the record.</source>
        <translation>
            <numerusform>%n newer proposal(s) were not queued (the queue holds %1); each is in the record.</numerusform>
            <numerusform>%n newer proposal(s) were not queued (the queue holds %1); each is in the record.</numerusform>
        </translation>
    </message>
    <message>
        <source>, fit error %1</source>
        <translation>, fit error %1</translation>
    </message>
    <message>
        <source>Estimate now</source>
        <translation>Estimate now</translation>
    </message>
    <message>
        <source>The target's current value, the proposed one, the estimator's value now and the change the proposal makes, in the law's normalized units</source>
        <translation>The target's current value, the proposed one, the estimator's value now and the change the proposal makes, in the law's normalized units</translation>
    </message>
    <message numerus="yes">
        <source>%n update(s) waiting for a decision.</source>
        <translation>
            <numerusform>%n update(s) waiting for a decision.</numerusform>
            <numerusform>%n update(s) waiting for a decision.</numerusform>
        </translation>
    </message>
    <message>
        <source>One proposal per target, renewed every %1 s of test time with the estimator's latest values (it replaces the one shown); Approve applies the values shown while they are current.</source>
        <translation>One proposal per target, renewed every %1 s of test time with the estimator's latest values (it replaces the one shown); Approve applies the values shown while they are current.</translation>
    </message>
    <message>
        <source>: stale (older than %1 s), wait for the next proposal</source>
        <translation>: stale (older than %1 s), wait for the next proposal</translation>
    </message>
    <message>
        <source>Approve offsets</source>
        <translation>Approve offsets</translation>
    </message>
    <message>
        <source>Reject offsets</source>
        <translation>Reject offsets</translation>
    </message>
    <message>
        <source>%1%2 (on its bound, no interval)</source>
        <translation>%1%2 (on its bound, no interval)</translation>
    </message>
    <message>
        <source>%1 +- %2%3 (95 %)</source>
        <translation>%1 +- %2%3 (95 %)</translation>
    </message>
    <message>
        <source>Offsets #%1 for the twins: u0 = %2, F0 = %3</source>
        <translation>Offsets #%1 for the twins: u0 = %2, F0 = %3</translation>
    </message>
    <message>
        <source>Found at t = %1 s (step %2) on %3 samples; the specimen&apos;s NRMSE %4 without them, %5 with them. They reach the twins (F = F_law(u - u0) + F0) only if you approve them, whatever the policy.</source>
        <translation>Found at t = %1 s (step %2) on %3 samples; the specimen&apos;s NRMSE %4 without them, %5 with them. They reach the twins (F = F_law(u - u0) + F0) only if you approve them, whatever the policy.</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PlotElementPicker</name>
    <message>
        <source>Element:</source>
        <translation>Element:</translation>
    </message>
    <message>
        <source>The element this plot shows</source>
        <translation>The element this plot shows</translation>
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
        <translation>%1: %2 at %3</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1: cannot be written (%2)</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>Autoscale</translation>
    </message>
    <message>
        <source>Channels</source>
        <translation>Channels</translation>
    </message>
    <message>
        <source>curve %1</source>
        <translation>curve %1</translation>
    </message>
    <message>
        <source>Export visible data as CSV...</source>
        <translation>Export visible data as CSV...</translation>
    </message>
    <message>
        <source>Export visible data</source>
        <translation>Export visible data</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV files (*.csv)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PreflightDialog</name>
    <message>
        <source>Pre-flight check</source>
        <translation>Pre-flight check</translation>
    </message>
    <message>
        <source>Integration and stability</source>
        <translation>Integration and stability</translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation>Integrator:</translation>
    </message>
    <message>
        <source>Time step dt [s]:</source>
        <translation>Time step dt [s]:</translation>
    </message>
    <message>
        <source>Steps:</source>
        <translation>Steps:</translation>
    </message>
    <message>
        <source>Ground motion:</source>
        <translation>Ground motion:</translation>
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
        <translation>omega_max dt [-] / limit:</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>unconditionally stable</source>
        <translation>unconditionally stable</translation>
    </message>
    <message>
        <source>Stable: %1</source>
        <translation>Stable: %1</translation>
    </message>
    <message>
        <source>UNSTABLE: %1%2</source>
        <translation>UNSTABLE: %1%2</translation>
    </message>
    <message>
        <source> (forced by the configuration)</source>
        <translation> (forced by the configuration)</translation>
    </message>
    <message>
        <source>Check:</source>
        <translation>Check:</translation>
    </message>
    <message>
        <source>Specimens: limits and initial measured values</source>
        <translation>Specimens: limits and initial measured values</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>Element</translation>
    </message>
    <message>
        <source>Max |d|</source>
        <translation>Max |d|</translation>
    </message>
    <message>
        <source>Max |F|</source>
        <translation>Max |F|</translation>
    </message>
    <message>
        <source>Max |Δd| per step</source>
        <translation>Max |Δd| per step</translation>
    </message>
    <message>
        <source>Measured d</source>
        <translation>Measured d</translation>
    </message>
    <message>
        <source>Measured F</source>
        <translation>Measured F</translation>
    </message>
    <message>
        <source>Measured d and F: what the specimen reported after the link was prepared, before any target was sent.</source>
        <translation>Measured d and F: what the specimen reported after the link was prepared, before any target was sent.</translation>
    </message>
    <message>
        <source>I confirm the zero offsets: with the specimen unloaded the actuator displacement and the load cell read zero.</source>
        <translation>I confirm the zero offsets: with the specimen unloaded the actuator displacement and the load cell read zero.</translation>
    </message>
    <message>
        <source>Start test</source>
        <translation>Start test</translation>
    </message>
    <message>
        <source>Please check:</source>
        <translation>Please check:</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>explicit Newmark</source>
        <translation>explicit Newmark</translation>
    </message>
    <message>
        <source>alpha-OS</source>
        <translation>alpha-OS</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>not measured</translation>
    </message>
    <message>
        <source>Measured d and F: what the specimen reported after the link was prepared, before any target was sent; for a specimen loaded by an earlier test, d is its last committed deformation and F is measured at the first step.</source>
        <translation>Measured d and F: what the specimen reported after the link was prepared, before any target was sent; for a specimen loaded by an earlier test, d is its last committed deformation and F is measured at the first step.</translation>
    </message>
    <message>
        <source>Specimen loaded by an earlier test</source>
        <translation>Specimen loaded by an earlier test</translation>
    </message>
    <message>
        <source>%1 has %L2 committed steps from an earlier test; its last committed deformation is %3 %4. This test starts from rest: its first target moves the specimen from there.</source>
        <translation>%1 has %L2 committed steps from an earlier test; its last committed deformation is %3 %4. This test starts from rest: its first target moves the specimen from there.</translation>
    </message>
    <message>
        <source>Its controller refused a fresh specimen (%1): replace the specimen at the controller and restart the controller without its state file, or continue on the loaded specimen.</source>
        <translation>Its controller refused a fresh specimen (%1): replace the specimen at the controller and restart the controller without its state file, or continue on the loaded specimen.</translation>
    </message>
    <message>
        <source>Choose: continue on the loaded specimen (its damage is part of this test), or a fresh specimen (its controller resets it to step 0, then this check is shown again).</source>
        <translation>Choose: continue on the loaded specimen (its damage is part of this test), or a fresh specimen (its controller resets it to step 0, then this check is shown again).</translation>
    </message>
    <message>
        <source>Continue on the loaded specimen</source>
        <translation>Continue on the loaded specimen</translation>
    </message>
    <message>
        <source>Fresh specimen</source>
        <translation>Fresh specimen</translation>
    </message>
    <message>
        <source>Reset the specimen</source>
        <translation>Reset the specimen</translation>
    </message>
    <message>
        <source>Continuing would move it by about %1 %2 at the first step, more than the increment limit %3 %2: the controller would hold the test. Choose a fresh specimen, or bring the specimen back to rest at the controller.</source>
        <translation>Continuing would move it by about %1 %2 at the first step, more than the increment limit %3 %2: the controller would hold the test. Choose a fresh specimen, or bring the specimen back to rest at the controller.</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReidentifyDialog</name>
    <message>
        <source>Re-identify</source>
        <translation>Re-identify</translation>
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
        <translation>none: the recorded settings</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Browse...</translation>
    </message>
    <message>
        <source>Override settings</source>
        <translation>Override settings</translation>
    </message>
    <message>
        <source>JSON (*.json);;All files (*)</source>
        <translation>JSON (*.json);;All files (*)</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>Method</translation>
    </message>
    <message>
        <source>Override (JSON)</source>
        <translation>Override (JSON)</translation>
    </message>
    <message>
        <source>{"model": ..., "updating": ...} merged into the recorded settings, as hsmu replay --config</source>
        <translation>{"model": ..., "updating": ...} merged into the recorded settings, as hsmu replay --config</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReplayEventList</name>
    <message>
        <source>Time [s]</source>
        <translation>Time [s]</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Step</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Kind</translation>
    </message>
    <message>
        <source>Event, alarm or note</source>
        <translation>Event, alarm or note</translation>
    </message>
    <message>
        <source>operator</source>
        <translation>operator</translation>
    </message>
    <message>
        <source>note</source>
        <translation>note</translation>
    </message>
    <message>
        <source>Double-click (or Enter) to jump to the step</source>
        <translation>Double-click (or Enter) to jump to the step</translation>
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
        <translation>Quantity</translation>
    </message>
    <message>
        <source>Value at the cursor</source>
        <translation>Value at the cursor</translation>
    </message>
    <message>
        <source>step</source>
        <translation>step</translation>
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
        <translation>Open record</translation>
    </message>
    <message>
        <source>HSMU records (*.h5 *.hdf5);;All files (*)</source>
        <translation>HSMU records (*.h5 *.hdf5);;All files (*)</translation>
    </message>
    <message>
        <source>Cannot open the record</source>
        <translation>Cannot open the record</translation>
    </message>
    <message>
        <source>HSMU Replay - %1 (%2)</source>
        <translation>HSMU Replay - %1 (%2)</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Replay</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Play</translation>
    </message>
    <message>
        <source> Speed </source>
        <translation> Speed </translation>
    </message>
    <message>
        <source>%1 x</source>
        <translation>%1 x</translation>
    </message>
    <message>
        <source>Test seconds per wall second</source>
        <translation>Test seconds per wall second</translation>
    </message>
    <message>
        <source>Scrub through the record</source>
        <translation>Scrub through the record</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source> t = %1 s   step %2 of %3 </source>
        <translation> t = %1 s   step %2 of %3 </translation>
    </message>
    <message>
        <source>Re-identify...</source>
        <translation>Re-identify...</translation>
    </message>
    <message>
        <source>Identify the specimen again with other settings and overlay the parameter history</source>
        <translation>Identify the specimen again with other settings and overlay the parameter history</translation>
    </message>
    <message>
        <source>identifying</source>
        <translation>identifying</translation>
    </message>
    <message>
        <source>Re-identifying the specimen</source>
        <translation>Re-identifying the specimen</translation>
    </message>
    <message>
        <source>re-identified (%1)</source>
        <translation>re-identified (%1)</translation>
    </message>
    <message>
        <source>Re-identification failed</source>
        <translation>Re-identification failed</translation>
    </message>
    <message>
        <source>Events, alarms and notes</source>
        <translation>Events, alarms and notes</translation>
    </message>
    <message>
        <source>Values at the cursor</source>
        <translation>Values at the cursor</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>Export time window as &amp;CSV...</source>
        <translation>Export time window as &amp;CSV...</translation>
    </message>
    <message>
        <source>Export time window</source>
        <translation>Export time window</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV files (*.csv)</translation>
    </message>
    <message>
        <source>Export &amp;plots (PNG, SVG or PDF)...</source>
        <translation>Export &amp;plots (PNG, SVG or PDF)...</translation>
    </message>
    <message>
        <source>Export plots</source>
        <translation>Export plots</translation>
    </message>
    <message>
        <source>PNG images (*.png);;SVG drawings (*.svg);;PDF documents (*.pdf)</source>
        <translation>PNG images (*.png);;SVG drawings (*.svg);;PDF documents (*.pdf)</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Close</translation>
    </message>
    <message>
        <source>&amp;Playback</source>
        <translation>&amp;Playback</translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation>Step &amp;back</translation>
    </message>
    <message>
        <source>Step &amp;forward</source>
        <translation>Step &amp;forward</translation>
    </message>
    <message>
        <source>To the &amp;start</source>
        <translation>To the &amp;start</translation>
    </message>
    <message>
        <source>To the &amp;end</source>
        <translation>To the &amp;end</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::RthsPanel</name>
    <message>
        <source>RTHS proposal #%1 rejected</source>
        <translation>RTHS proposal #%1 rejected</translation>
    </message>
    <message>
        <source>RTHS proposal #%1 approved</source>
        <translation>RTHS proposal #%1 approved</translation>
    </message>
    <message>
        <source>Damper twin</source>
        <translation>Damper twin</translation>
    </message>
    <message>
        <source>Tracking</source>
        <translation>Tracking</translation>
    </message>
    <message>
        <source>Go on with the held run from the tick where it held (refused while a limit is still breached)</source>
        <translation>Go on with the held run from the tick where it held (refused while a limit is still breached)</translation>
    </message>
    <message>
        <source>Not resumed: %1</source>
        <translation>Not resumed: %1</translation>
    </message>
    <message>
        <source>RTHS run not resumed: %1</source>
        <translation>RTHS run not resumed: %1</translation>
    </message>
    <message>
        <source>RTHS resume</source>
        <translation>RTHS resume</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Resume</translation>
    </message>
    <message>
        <source>Resumed</source>
        <translation>Resumed</translation>
    </message>
    <message>
        <source>No RTHS run yet.</source>
        <translation>No RTHS run yet.</translation>
    </message>
    <message>
        <source>Run:</source>
        <translation>Run:</translation>
    </message>
    <message>
        <source>Benchmark case %1</source>
        <translation>Benchmark case %1</translation>
    </message>
    <message>
        <source>Configuration file</source>
        <translation>Configuration file</translation>
    </message>
    <message>
        <source>RTHS configuration (.json)</source>
        <translation>RTHS configuration (.json)</translation>
    </message>
    <message>
        <source>Choose an RTHS configuration file</source>
        <translation>Choose an RTHS configuration file</translation>
    </message>
    <message>
        <source>Pace:</source>
        <translation>Pace:</translation>
    </message>
    <message>
        <source>Fast (simulated)</source>
        <translation>Fast (simulated)</translation>
    </message>
    <message>
        <source>Real time</source>
        <translation>Real time</translation>
    </message>
    <message>
        <source>Duration:</source>
        <translation>Duration:</translation>
    </message>
    <message>
        <source>whole record</source>
        <translation>whole record</translation>
    </message>
    <message>
        <source>Stop the run after this many seconds of test time (0: the whole record)</source>
        <translation>Stop the run after this many seconds of test time (0: the whole record)</translation>
    </message>
    <message>
        <source>Start RTHS</source>
        <translation>Start RTHS</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Hold</translation>
    </message>
    <message>
        <source>Hold the loop before its next tick (Resume goes on from there)</source>
        <translation>Hold the loop before its next tick (Resume goes on from there)</translation>
    </message>
    <message>
        <source>Emergency hold</source>
        <translation>Emergency hold</translation>
    </message>
    <message>
        <source>Live tracking</source>
        <translation>Live tracking</translation>
    </message>
    <message>
        <source>Warning above</source>
        <translation>Warning above</translation>
    </message>
    <message>
        <source>Critical above</source>
        <translation>Critical above</translation>
    </message>
    <message>
        <source>J1 delay</source>
        <translation>J1 delay</translation>
    </message>
    <message>
        <source>J2 tracking error</source>
        <translation>J2 tracking error</translation>
    </message>
    <message>
        <source>RTHS configuration</source>
        <translation>RTHS configuration</translation>
    </message>
    <message>
        <source>Configuration (*.json)</source>
        <translation>Configuration (*.json)</translation>
    </message>
    <message>
        <source>choose an RTHS configuration file</source>
        <translation>choose an RTHS configuration file</translation>
    </message>
    <message>
        <source>Cannot start the RTHS run: %1</source>
        <translation>Cannot start the RTHS run: %1</translation>
    </message>
    <message>
        <source>RTHS run '%1' started</source>
        <translation>RTHS run '%1' started</translation>
    </message>
    <message>
        <source>RTHS hold</source>
        <translation>RTHS hold</translation>
    </message>
    <message>
        <source>RTHS emergency hold</source>
        <translation>RTHS emergency hold</translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation>Not applied: %1</translation>
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
        <translation>Amplitude error: %1 %</translation>
    </message>
    <message>
        <source>Amplitude error: -- %</source>
        <translation>Amplitude error: -- %</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>Finished: %1 ticks (%2 s); whole run J1 %3 ms, J2 %4 %</source>
        <translation>Finished: %1 ticks (%2 s); whole run J1 %3 ms, J2 %4 %</translation>
    </message>
    <message>
        <source>RTHS run finished: %1 ticks</source>
        <translation>RTHS run finished: %1 ticks</translation>
    </message>
    <message>
        <source>Held after %1 ticks: %2</source>
        <translation>Held after %1 ticks: %2</translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation>Controller:</translation>
    </message>
    <message>
        <source>built-in virtual lab, or tcp://HOST:PORT of hsmu-controller --rths</source>
        <translation>built-in virtual lab, or tcp://HOST:PORT of hsmu-controller --rths</translation>
    </message>
    <message>
        <source>Empty: the loop runs in the console. tcp://HOST:PORT: monitor the loop hsmu-controller --rths runs (its token from HSMU_CONTROLLER_TOKEN)</source>
        <translation>Empty: the loop runs in the console. tcp://HOST:PORT: monitor the loop hsmu-controller --rths runs (its token from HSMU_CONTROLLER_TOKEN)</translation>
    </message>
    <message>
        <source>controller: an RTHS loop is monitored over tcp://HOST:PORT (hsmu-controller --rths)</source>
        <translation>controller: an RTHS loop is monitored over tcp://HOST:PORT (hsmu-controller --rths)</translation>
    </message>
    <message>
        <source>real time; pre-flight: %1</source>
        <translation>real time; pre-flight: %1</translation>
    </message>
    <message>
        <source>fast; pre-flight: %1</source>
        <translation>fast; pre-flight: %1</translation>
    </message>
    <message>
        <source>on the controller %1:%2</source>
        <translation>on the controller %1:%2</translation>
    </message>
    <message>
        <source>Running '%1' at %2 Hz (%3)</source>
        <translation>Running '%1' at %2 Hz (%3)</translation>
    </message>
    <message>
        <source>The RTHS run could not be followed: %1</source>
        <translation>The RTHS run could not be followed: %1</translation>
    </message>
    <message>
        <source>Record folder:</source>
        <translation>Record folder:</translation>
    </message>
    <message>
        <source>not recorded</source>
        <translation>not recorded</translation>
    </message>
    <message>
        <source>Every tick of a run from this view goes to record.h5 in this folder (record-2.h5, record-3.h5, ... when taken: nothing is overwritten); empty: not recorded</source>
        <translation>Every tick of a run from this view goes to record.h5 in this folder (record-2.h5, record-3.h5, ... when taken: nothing is overwritten); empty: not recorded</translation>
    </message>
    <message>
        <source>Recorded on the controller, not by the console: %1</source>
        <translation>Recorded on the controller, not by the console: %1</translation>
    </message>
    <message>
        <source>Not recorded (no record folder)</source>
        <translation>Not recorded (no record folder)</translation>
    </message>
    <message>
        <source>Recording every tick to %1</source>
        <translation>Recording every tick to %1</translation>
    </message>
    <message>
        <source>Recorded on the controller, not by the console (waiting for the controller&apos;s description)</source>
        <translation>Recorded on the controller, not by the console (waiting for the controller&apos;s description)</translation>
    </message>
    <message>
        <source>The record %1 is incomplete: %2</source>
        <translation>The record %1 is incomplete: %2</translation>
    </message>
    <message>
        <source>Recorded %1 ticks to %2</source>
        <translation>Recorded %1 ticks to %2</translation>
    </message>
    <message>
        <source>No estimate: the command&apos;s RMS %1 mm is below %2 mm</source>
        <translation>No estimate: the command&apos;s RMS %1 mm is below %2 mm</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::RthsSession</name>
    <message>
        <source>no controller&apos;s RTHS run is going</source>
        <translation>no controller&apos;s RTHS run is going</translation>
    </message>
    <message>
        <source>this RTHS run has no damper twin</source>
        <translation>this RTHS run has no damper twin</translation>
    </message>
    <message>
        <source>the link to the controller is closed</source>
        <translation>the link to the controller is closed</translation>
    </message>
    <message>
        <source>no RTHS run is going</source>
        <translation>no RTHS run is going</translation>
    </message>
    <message>
        <source>no held RTHS run to resume</source>
        <translation>no held RTHS run to resume</translation>
    </message>
    <message>
        <source>an RTHS run is already going</source>
        <translation>an RTHS run is already going</translation>
    </message>
    <message>
        <source>refused in pre-flight: %1</source>
        <translation>refused in pre-flight: %1</translation>
    </message>
    <message>
        <source>the controller's (%1:%2)</source>
        <translation>the controller's (%1:%2)</translation>
    </message>
    <message>
        <source>the link to the controller was lost: %1 (the controller holds the loop per its --monitor-loss policy)</source>
        <translation>the link to the controller was lost: %1 (the controller holds the loop per its --monitor-loss policy)</translation>
    </message>
    <message>
        <source>the record cannot be created in %1: %2</source>
        <translation>the record cannot be created in %1: %2</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SettingsDialog</name>
    <message>
        <source>Settings</source>
        <translation>Settings</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>System default</translation>
    </message>
    <message>
        <source>Clear recent files</source>
        <translation>Clear recent files</translation>
    </message>
    <message>
        <source>empty: tests are not recorded</source>
        <translation>empty: tests are not recorded</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Browse...</translation>
    </message>
    <message>
        <source>Record folder</source>
        <translation>Record folder</translation>
    </message>
    <message>
        <source>Record folder (HDF5):</source>
        <translation>Record folder (HDF5):</translation>
    </message>
    <message>
        <source>Language:</source>
        <translation>Language:</translation>
    </message>
    <message>
        <source>Recent files:</source>
        <translation>Recent files:</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>A new language applies at once, to every window.</source>
        <translation>A new language applies at once, to every window.</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SetupPanel</name>
    <message>
        <source>Record's sample step [s]:</source>
        <translation>Record's sample step [s]:</translation>
    </message>
    <message>
        <source>The time between the record's samples. A file of acceleration values only (one column) needs it; an AT2 header or a time column gives its own. Not the integration step dt.</source>
        <translation>The time between the record's samples. A file of acceleration values only (one column) needs it; an AT2 header or a time column gives its own. Not the integration step dt.</translation>
    </message>
    <message>
        <source>from the file</source>
        <translation>from the file</translation>
    </message>
    <message>
        <source>No configuration loaded: choose a preset or open a file.</source>
        <translation>No configuration loaded: choose a preset or open a file.</translation>
    </message>
    <message>
        <source>Safety limits (0 = none; the specimen's units)</source>
        <translation>Safety limits (0 = none; the specimen's units)</translation>
    </message>
    <message>
        <source>Specimen</source>
        <translation>Specimen</translation>
    </message>
    <message>
        <source>Max |d|</source>
        <translation>Max |d|</translation>
    </message>
    <message>
        <source>Max |F|</source>
        <translation>Max |F|</translation>
    </message>
    <message>
        <source>Max |Δd| per step</source>
        <translation>Max |Δd| per step</translation>
    </message>
    <message>
        <source>Apply (reload the test)</source>
        <translation>Apply (reload the test)</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Run</translation>
    </message>
    <message>
        <source>the configuration's record</source>
        <translation>the configuration's record</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Browse...</translation>
    </message>
    <message>
        <source>Ground motion file:</source>
        <translation>Ground motion file:</translation>
    </message>
    <message>
        <source>Scale [-]:</source>
        <translation>Scale [-]:</translation>
    </message>
    <message>
        <source>Time step dt [s]:</source>
        <translation>Time step dt [s]:</translation>
    </message>
    <message>
        <source>whole record</source>
        <translation>whole record</translation>
    </message>
    <message>
        <source>Duration [s]:</source>
        <translation>Duration [s]:</translation>
    </message>
    <message>
        <source>explicit Newmark</source>
        <translation>explicit Newmark</translation>
    </message>
    <message>
        <source>alpha-OS</source>
        <translation>alpha-OS</translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation>Integrator:</translation>
    </message>
    <message>
        <source>alpha-OS alpha [-]:</source>
        <translation>alpha-OS alpha [-]:</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Controller</translation>
    </message>
    <message>
        <source>built-in virtual lab</source>
        <translation>built-in virtual lab</translation>
    </message>
    <message>
        <source>hsmu-controller over TCP</source>
        <translation>hsmu-controller over TCP</translation>
    </message>
    <message>
        <source>Specimens driven by:</source>
        <translation>Specimens driven by:</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>Host:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <source>Online model updating</source>
        <translation>Online model updating</translation>
    </message>
    <message>
        <source>enabled</source>
        <translation>enabled</translation>
    </message>
    <message>
        <source>Fit-error threshold [-]:</source>
        <translation>Fit-error threshold [-]:</translation>
    </message>
    <message>
        <source>Ground motion record</source>
        <translation>Ground motion record</translation>
    </message>
    <message>
        <source>Ground motions (*.AT2 *.at2 *.txt *.csv *.dat);;All files (*)</source>
        <translation>Ground motions (*.AT2 *.at2 *.txt *.csv *.dat);;All files (*)</translation>
    </message>
    <message>
        <source>Configuration: %1
%2</source>
        <translation>Configuration: %1
%2</translation>
    </message>
    <message>
        <source>(built in)</source>
        <translation>(built in)</translation>
    </message>
    <message>
        <source>built-in %1 record</source>
        <translation>built-in %1 record</translation>
    </message>
    <message>
        <source>d in %1, F in %2</source>
        <translation>d in %1, F in %2</translation>
    </message>
    <message>
        <source>no configuration loaded</source>
        <translation>no configuration loaded</translation>
    </message>
    <message>
        <source>safety limit of %1: '%2' is not a number &gt;= 0</source>
        <translation>safety limit of %1: '%2' is not a number &gt;= 0</translation>
    </message>
    <message>
        <source>this configuration has no updating section to enable</source>
        <translation>this configuration has no updating section to enable</translation>
    </message>
    <message>
        <source>OpenFresco SimApp site</source>
        <translation>OpenFresco SimApp site</translation>
    </message>
    <message>
        <source>OpenFresco GenericTCP controller</source>
        <translation>OpenFresco GenericTCP controller</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>The token hsmu-controller --token expects; not saved</source>
        <translation>The token hsmu-controller --token expects; not saved</translation>
    </message>
    <message>
        <source>Token:</source>
        <translation>Token:</translation>
    </message>
    <message>
        <source>Test link</source>
        <translation>Test link</translation>
    </message>
    <message>
        <source>Connect to the controller now (the test is prepared; nothing moves before the pre-flight check)</source>
        <translation>Connect to the controller now (the test is prepared; nothing moves before the pre-flight check)</translation>
    </message>
    <message>
        <source>When updates are applied is chosen in the Pending updates panel (one setting for the test).</source>
        <translation>When updates are applied is chosen in the Pending updates panel (one setting for the test).</translation>
    </message>
    <message>
        <source>OpenSees adapter element (numerical substructure)</source>
        <translation>OpenSees adapter element (numerical substructure)</translation>
    </message>
    <message>
        <source>hsmu-controller over TLS (the configuration's tls block)</source>
        <translation>hsmu-controller over TLS (the configuration's tls block)</translation>
    </message>
    <message>
        <source>OpenSees listens: start the model with its `element adapter ... PORT` first (its analyze must have at least the test's steps). A step is final once the next one is sent: after a hold the test cannot repeat it.</source>
        <translation>OpenSees listens: start the model with its `element adapter ... PORT` first (its analyze must have at least the test's steps). A step is final once the next one is sent: after a hold the test cannot repeat it.</translation>
    </message>
    <message>
        <source>synthetic</source>
        <translation>synthetic</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SetupSketchView</name>
    <message>
        <source>%1: no 2-D drawing of its setup %2 (a 3-D or aggregated setup); its actuators are in the plot.</source>
        <translation>%1: no 2-D drawing of its setup %2 (a 3-D or aggregated setup); its actuators are in the plot.</translation>
    </message>
    <message>
        <source>deformed shape x%1 (solid), at rest (dashed)</source>
        <translation>deformed shape x%1 (solid), at rest (dashed)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SiteHealthLabel</name>
    <message>
        <source>down</source>
        <translation>down</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>last fault: %1</source>
        <translation>last fault: %1</translation>
    </message>
    <message>
        <source> (faults: %1)</source>
        <translation> (faults: %1)</translation>
    </message>
    <message>
        <source>connected, %1 ms</source>
        <translation>connected, %1 ms</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>connected</translation>
    </message>
    <message>
        <source>link: %1</source>
        <translation>link: %1</translation>
    </message>
    <message>
        <source>no link</source>
        <translation>no link</translation>
    </message>
    <message>
        <source>(connects at start)</source>
        <translation>(connects at start)</translation>
    </message>
    <message>
        <source>built-in virtual lab</source>
        <translation>built-in virtual lab</translation>
    </message>
    <message>
        <source>%1: built-in virtual lab</source>
        <translation>%1: built-in virtual lab</translation>
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
        <translation>Sites</translation>
    </message>
    <message>
        <source>Site</source>
        <translation>Site</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Address</translation>
    </message>
    <message>
        <source>Specimens</source>
        <translation>Specimens</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>Health</translation>
    </message>
    <message>
        <source>the controller above</source>
        <translation>the controller above</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SynchronizationPlot</name>
    <message>
        <source>Synchronization: measured against desired</source>
        <translation>Synchronization: measured against desired</translation>
    </message>
    <message>
        <source>desired displacement y [mm]</source>
        <translation>desired displacement y [mm]</translation>
    </message>
    <message>
        <source>measured displacement xm [mm]</source>
        <translation>measured displacement xm [mm]</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>measured</translation>
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
    <message>
        <source>not recording</source>
        <translation>not recording</translation>
    </message>
    <message>
        <source>recording: %1/%2</source>
        <translation>recording: %1/%2</translation>
    </message>
    <message>
        <source>%1, %2 left</source>
        <translation>%1, %2 left</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TestWorker</name>
    <message>
        <source>link restored: the test resumed after an automatic reconnect</source>
        <translation>link restored: the test resumed after an automatic reconnect</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>emergency hold by the operator</translation>
    </message>
    <message>
        <source>the record cannot be written: %1</source>
        <translation>the record cannot be written: %1</translation>
    </message>
    <message>
        <source>this test has no model updating</source>
        <translation>this test has no model updating</translation>
    </message>
    <message>
        <source>%1: the lower bound must be a number not above the upper bound</source>
        <translation>%1: the lower bound must be a number not above the upper bound</translation>
    </message>
    <message>
        <source>%1: bounds [%2, %3] refused (they would not keep the law admissible)</source>
        <translation>%1: bounds [%2, %3] refused (they would not keep the law admissible)</translation>
    </message>
    <message>
        <source>%1: the %2 cannot lock this parameter</source>
        <translation>%1: the %2 cannot lock this parameter</translation>
    </message>
    <message>
        <source>update #%1 was not applied (no longer pending, or refused by the law; see the alarms)</source>
        <translation>update #%1 was not applied (no longer pending, or refused by the law; see the alarms)</translation>
    </message>
    <message>
        <source>update #%1 is no longer pending</source>
        <translation>update #%1 is no longer pending</translation>
    </message>
    <message>
        <source>offsets #%1 are no longer pending</source>
        <translation>offsets #%1 are no longer pending</translation>
    </message>
    <message>
        <source>offsets #%1 were not applied: %2</source>
        <translation>offsets #%1 were not applied: %2</translation>
    </message>
    <message>
        <source>the fit-error threshold must be a positive number</source>
        <translation>the fit-error threshold must be a positive number</translation>
    </message>
    <message>
        <source>the note was not kept: this test is not recorded</source>
        <translation>the note was not kept: this test is not recorded</translation>
    </message>
    <message>
        <source>link fault (%1): reconnecting in %2 s (attempt %3 of %4)</source>
        <translation>link fault (%1): reconnecting in %2 s (attempt %3 of %4)</translation>
    </message>
    <message>
        <source>the note was not kept: %1</source>
        <translation>the note was not kept: %1</translation>
    </message>
    <message>
        <source>update #%1 was not applied: the estimate has moved on and #%2 replaced it; check #%2 and approve it if it is right</source>
        <translation>update #%1 was not applied: the estimate has moved on and #%2 replaced it; check #%2 and approve it if it is right</translation>
    </message>
    <message>
        <source>update #%1 was not applied: it is older than one proposal interval (%2 s) and no longer what the estimator believes; wait for the next proposal</source>
        <translation>update #%1 was not applied: it is older than one proposal interval (%2 s) and no longer what the estimator believes; wait for the next proposal</translation>
    </message>
    <message>
        <source>update #%1 is no longer pending: #%2 replaced it</source>
        <translation>update #%1 is no longer pending: #%2 replaced it</translation>
    </message>
    <message>
        <source>the controller of %1 refused a fresh specimen: %2; replace the specimen at the controller, or continue on the loaded specimen</source>
        <translation>the controller of %1 refused a fresh specimen: %2; replace the specimen at the controller, or continue on the loaded specimen</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TrackingHistoryPlot</name>
    <message>
        <source>Delay and amplitude error (moving window)</source>
        <translation>Delay and amplitude error (moving window)</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>time [s]</translation>
    </message>
    <message>
        <source>delay [ms]</source>
        <translation>delay [ms]</translation>
    </message>
    <message>
        <source>amplitude error [%]</source>
        <translation>amplitude error [%]</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::RthsTwinPanel</name>
    <message>
        <source>Proposal #%1 refused: %2</source>
        <translation>Proposal #%1 refused: %2</translation>
    </message>
    <message>
        <source>Proposal #%1 applied before tick %2</source>
        <translation>Proposal #%1 applied before tick %2</translation>
    </message>
    <message>
        <source>Proposal #%1 rejected before tick %2: nothing applied</source>
        <translation>Proposal #%1 rejected before tick %2: nothing applied</translation>
    </message>
    <message>
        <source>Proposal #%1 %2</source>
        <translation>Proposal #%1 %2</translation>
    </message>
    <message>
        <source>Proposal #%1 before tick %2: waiting for your approval</source>
        <translation>Proposal #%1 before tick %2: waiting for your approval</translation>
    </message>
    <message>
        <source>Reject</source>
        <translation>Reject</translation>
    </message>
    <message>
        <source>Apply the selected proposal before the loop&apos;s next tick (refused if outside the bounds)</source>
        <translation>Apply the selected proposal before the loop&apos;s next tick (refused if outside the bounds)</translation>
    </message>
    <message>
        <source>Approve</source>
        <translation>Approve</translation>
    </message>
    <message>
        <source>Proposals waiting for approval (the controller&apos;s identification)</source>
        <translation>Proposals waiting for approval (the controller&apos;s identification)</translation>
    </message>
    <message>
        <source>Proposed values</source>
        <translation>Proposed values</translation>
    </message>
    <message>
        <source>Fit error</source>
        <translation>Fit error</translation>
    </message>
    <message>
        <source>Tick (time)</source>
        <translation>Tick (time)</translation>
    </message>
    <message>
        <source>Proposal</source>
        <translation>Proposal</translation>
    </message>
    <message>
        <source>Applied before tick %1 (t = %2 s; %3): %4</source>
        <translation>Applied before tick %1 (t = %2 s; %3): %4</translation>
    </message>
    <message>
        <source>Refused: %1</source>
        <translation>Refused: %1</translation>
    </message>
    <message>
        <source>Refused before tick %1: %2</source>
        <translation>Refused before tick %1: %2</translation>
    </message>
    <message>
        <source>Sent: applied before the loop&apos;s next tick, or refused with the reason</source>
        <translation>Sent: applied before the loop&apos;s next tick, or refused with the reason</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>Not sent: %1</translation>
    </message>
    <message>
        <source>type at least one new value</source>
        <translation>type at least one new value</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: &apos;%2&apos; is not a number</translation>
    </message>
    <message>
        <source>Damper twin: none in this run</source>
        <translation>Damper twin: none in this run</translation>
    </message>
    <message>
        <source>Damper twin (storey of DOF %1), values in its scales uRef, fRef</source>
        <translation>Damper twin (storey of DOF %1), values in its scales uRef, fRef</translation>
    </message>
    <message>
        <source>Apply the new values to the twin before the loop&apos;s next tick (checked against the bounds first)</source>
        <translation>Apply the new values to the twin before the loop&apos;s next tick (checked against the bounds first)</translation>
    </message>
    <message>
        <source>Send update</source>
        <translation>Send update</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>New value</translation>
    </message>
    <message>
        <source>Bounds</source>
        <translation>Bounds</translation>
    </message>
    <message>
        <source>Physical value</source>
        <translation>Physical value</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
</context>
</TS>
