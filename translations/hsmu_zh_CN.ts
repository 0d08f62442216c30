<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>ActuatorLimitText</name>
    <message>
        <source>%1, actuator &apos;%2&apos; (%3)</source>
        <translation>%1，作动器“%2”（%3）</translation>
    </message>
    <message>
        <source>force control</source>
        <translation>力控制</translation>
    </message>
    <message>
        <source>displacement control</source>
        <translation>位移控制</translation>
    </message>
    <message>
        <source>stroke |s|</source>
        <translation>行程 |s|</translation>
    </message>
    <message>
        <source>force |F|</source>
        <translation>力 |F|</translation>
    </message>
    <message>
        <source>stroke increment |Δs| per step</source>
        <translation>每步行程增量 |Δs|</translation>
    </message>
    <message>
        <source>PASS  %1: %2 up to %3 %4 (t = %5 s), within the limit %6 %4</source>
        <translation>通过  %1：%2 最大 %3 %4（t = %5 s），在限值 %6 %4 以内</translation>
    </message>
    <message>
        <source>FAIL  %1: %2 reaches %3 %4 (t = %5 s), past the limit %6 %4: the test will hold at that step</source>
        <translation>不通过  %1：%2 达到 %3 %4（t = %5 s），超过限值 %6 %4：试验将在该步暂停</translation>
    </message>
    <message>
        <source>%1: %2 limit %3 %4, checked at every step (it depends on the specimen&apos;s response)</source>
        <translation>%1：%2 限值 %3 %4，每步检查（取决于试件的响应）</translation>
    </message>
    <message>
        <source>%1: no %2 limit</source>
        <translation>%1：无 %2 限值</translation>
    </message>
</context>
<context>
    <name>AlarmText</name>
    <message>
        <source>test resumed after an automatic reconnect</source>
        <translation>自动重连后试验继续</translation>
    </message>
    <message>
        <source>operator hold</source>
        <translation>操作员暂停</translation>
    </message>
    <message>
        <source>predicted displacement is not finite</source>
        <translation>预测位移不是有限值</translation>
    </message>
    <message>
        <source>restoring force or response is not finite</source>
        <translation>恢复力或响应不是有限值</translation>
    </message>
    <message>
        <source>test held: %1</source>
        <translation>试验已暂停：%1</translation>
    </message>
    <message>
        <source>test resumed</source>
        <translation>试验已继续</translation>
    </message>
    <message>
        <source>model error %1 % above the threshold %2 %</source>
        <translation>模型误差 %1 % 高于阈值 %2 %</translation>
    </message>
    <message>
        <source>sudden strength loss: measured force %1 short of the model&apos;s by %2</source>
        <translation>强度突然丧失：实测力 %1 比模型力低 %2</translation>
    </message>
    <message>
        <source>identification step rejected: %1</source>
        <translation>识别步被拒绝：%1</translation>
    </message>
    <message>
        <source>actuator tracking error J2 = %1 % (delay J1 = %2 s)</source>
        <translation>作动器跟踪误差 J2 = %1 %（延迟 J1 = %2 s）</translation>
    </message>
    <message>
        <source>%1 has been at its bound %2 for %3 s</source>
        <translation>%1 已在其边界 %2 停留 %3 s</translation>
    </message>
    <message>
        <source>update not applied: the approval queue is full (%1 proposals pending); this and later offers are in the record until the operator decides</source>
        <translation>更新未应用：审批队列已满（%1 个提议待定）；此后的提议在操作员决定前都会记录</translation>
    </message>
    <message>
        <source>offsets proposed for the twins: u0 = %1, F0 = %2 (they apply only when the operator approves them)</source>
        <translation>为孪生模型提议的偏移：u0 = %1，F0 = %2（仅在操作员批准后才应用）</translation>
    </message>
    <message>
        <source>%1: omega_max dt = %2 (omega_max = %3 rad/s, dt = %4 s) within the limit %5</source>
        <translation>%1：omega_max dt = %2（omega_max = %3 rad/s，dt = %4 s）在极限 %5 之内</translation>
    </message>
    <message>
        <source>%1 is unstable for this model: omega_max dt = %2 exceeds %3 (omega_max = %4 rad/s, dt = %5 s); use dt &lt;= %6 s or the alphaOS integrator</source>
        <translation>%1 对该模型不稳定：omega_max dt = %2 超过 %3（omega_max = %4 rad/s，dt = %5 s）；请使用 dt &lt;= %6 s 或 alphaOS 积分器</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <source>operator at the console</source>
        <translation>控制台操作员</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>操作员触发紧急保持</translation>
    </message>
    <message>
        <source>emergency hold: %1 (%2)</source>
        <translation>紧急保持：%1（%2）</translation>
    </message>
    <message>
        <source>emergency hold: %1</source>
        <translation>紧急保持：%1</translation>
    </message>
    <message>
        <source>target deformation is not a finite number</source>
        <translation>目标变形不是有限数</translation>
    </message>
    <message>
        <source>target deformation |d| = %1 exceeds the limit %2</source>
        <translation>目标变形 |d| = %1 超过限值 %2</translation>
    </message>
    <message>
        <source>target increment |d - d_last| = %1 exceeds the limit %2</source>
        <translation>目标增量 |d - d_上一步| = %1 超过限值 %2</translation>
    </message>
    <message>
        <source>measured force is not a finite number</source>
        <translation>实测力不是有限数</translation>
    </message>
    <message>
        <source>measured force |F| = %1 exceeds the limit %2</source>
        <translation>实测力 |F| = %1 超过限值 %2</translation>
    </message>
    <message>
        <source>measured deformation is not a finite number</source>
        <translation>实测变形不是有限数</translation>
    </message>
    <message>
        <source>measured deformation |d| = %1 exceeds the limit %2 (+%3 % tolerance)</source>
        <translation>实测变形 |d| = %1 超过限值 %2（容差 +%3 %）</translation>
    </message>
    <message>
        <source>%1 (forced by the operator)</source>
        <translation>%1（由操作员强制）</translation>
    </message>
    <message>
        <source>updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), limit %4; K0 and damping kept from the start: the explicit integration of the updated model may diverge</source>
        <translation>更新后的模型：omega_max dt = %1（omega_max = %2 rad/s，开始时为 %3），限值 %4；K0 和阻尼保持开始时的值：更新后模型的显式积分可能发散</translation>
    </message>
    <message>
        <source>updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), limit %4; K0 and damping kept from the start</source>
        <translation>更新后的模型：omega_max dt = %1（omega_max = %2 rad/s，开始时为 %3），限值 %4；K0 和阻尼保持开始时的值</translation>
    </message>
    <message>
        <source>auxiliary model did not converge at deformation %1</source>
        <translation>辅助模型在变形 %1 处未收敛</translation>
    </message>
    <message>
        <source>stopped by the operator</source>
        <translation>由操作员停止</translation>
    </message>
    <message>
        <source>synthetic Kanai-Tajimi (seed %1)</source>
        <translation>合成 Kanai-Tajimi（种子 %1）</translation>
    </message>
    <message>
        <source>link to %1 is down (%2); resume to reconnect</source>
        <translation>到 %1 的链路已断开（%2）；继续以重新连接</translation>
    </message>
    <message>
        <source>link to %1: %2</source>
        <translation>到 %1 的链路：%2</translation>
    </message>
    <message>
        <source>controller at %1: %2</source>
        <translation>位于 %1 的控制器：%2</translation>
    </message>
    <message>
        <source>TCP link is holding: %1</source>
        <translation>TCP 链路已暂停：%1</translation>
    </message>
    <message>
        <source>no connection to %1 within %2 s</source>
        <translation>%2 秒内未能连接到 %1</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>无法连接到 %1：%2</translation>
    </message>
    <message>
        <source>cannot resolve %1: %2</source>
        <translation>无法解析 %1：%2</translation>
    </message>
    <message>
        <source>the controller closed the connection</source>
        <translation>控制器关闭了连接</translation>
    </message>
    <message>
        <source>the peer closed the connection</source>
        <translation>对端关闭了连接</translation>
    </message>
    <message>
        <source>connection lost while sending: %1</source>
        <translation>发送时连接丢失：%1</translation>
    </message>
    <message>
        <source>connection lost: %1</source>
        <translation>连接丢失：%1</translation>
    </message>
    <message>
        <source>malformed frame from the controller: %1</source>
        <translation>来自控制器的帧格式错误：%1</translation>
    </message>
    <message>
        <source>the controller was silent for %1 s</source>
        <translation>控制器 %1 秒无响应</translation>
    </message>
    <message>
        <source>not connected: %1</source>
        <translation>未连接：%1</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>no reply within %1 s</source>
        <translation>%1 秒内无应答</translation>
    </message>
    <message>
        <source>closed by the console</source>
        <translation>已由控制台关闭</translation>
    </message>
    <message>
        <source>closed by an emergency hold</source>
        <translation>因紧急暂停而关闭</translation>
    </message>
    <message>
        <source>no answer to the hello</source>
        <translation>握手（hello）无应答</translation>
    </message>
    <message>
        <source>no measurement for step %1</source>
        <translation>第 %1 步无测量值</translation>
    </message>
    <message>
        <source>the controller&apos;s specimen is at step %1 but the test committed %2 (was it restarted without its --state file?); cannot resume without a jump</source>
        <translation>控制器的试件处于第 %1 步，而试验已提交 %2 步（是否在没有 --state 文件的情况下重启了？）；无法在不跳步的情况下继续</translation>
    </message>
    <message>
        <source>specimen &apos;%1&apos; holds: %2</source>
        <translation>试件“%1”已暂停：%2</translation>
    </message>
    <message>
        <source>interlock: %1</source>
        <translation>联锁：%1</translation>
    </message>
    <message>
        <source>specimen fault: %1</source>
        <translation>试件故障：%1</translation>
    </message>
    <message>
        <source>controller fault: %1</source>
        <translation>控制器故障：%1</translation>
    </message>
    <message>
        <source>actuator position |d| = %1 exceeds the limit %2</source>
        <translation>作动器位置 |d| = %1 超过限值 %2</translation>
    </message>
    <message>
        <source>console hold</source>
        <translation>控制台暂停</translation>
    </message>
    <message>
        <source>wrong token</source>
        <translation>令牌错误</translation>
    </message>
    <message>
        <source>another console session is running a test on this controller (one session at a time)</source>
        <translation>另一个控制台会话正在此控制器上运行试验（一次只允许一个会话）</translation>
    </message>
    <message>
        <source>this controller has no specimen named &apos;%1&apos;</source>
        <translation>此控制器没有名为“%1”的试件</translation>
    </message>
    <message>
        <source>held from the previous console session: %1</source>
        <translation>自上一个控制台会话起处于暂停：%1</translation>
    </message>
    <message>
        <source>virtual specimen (%1 law, force noise std %2, %3 actuator, fracture event)</source>
        <translation>虚拟试件（%1 本构，力噪声标准差 %2，%3 作动器，断裂事件）</translation>
    </message>
    <message>
        <source>virtual specimen (%1 law, force noise std %2, %3 actuator)</source>
        <translation>虚拟试件（%1 本构，力噪声标准差 %2，%3 作动器）</translation>
    </message>
    <message>
        <source>specimen &apos;%1&apos; on hsmu-controller (%2 law, force noise std %3, %4 actuator, %5 pace, %6 Hz predictor-corrector, fracture event), %7 committed steps</source>
        <translation>hsmu-controller 上的试件“%1”（%2 本构，力噪声标准差 %3，%4 作动器，%5 节奏，%6 Hz 预测-校正，断裂事件），已提交 %7 步</translation>
    </message>
    <message>
        <source>specimen &apos;%1&apos; on hsmu-controller (%2 law, force noise std %3, %4 actuator, %5 pace, %6 Hz predictor-corrector), %7 committed steps</source>
        <translation>hsmu-controller 上的试件“%1”（%2 本构，力噪声标准差 %3，%4 作动器，%5 节奏，%6 Hz 预测-校正），已提交 %7 步</translation>
    </message>
    <message>
        <source>TCP link %1 to %2</source>
        <translation>TCP 链路 %1，连接 %2</translation>
    </message>
    <message>
        <source>specimen &apos;%1&apos;</source>
        <translation>试件“%1”</translation>
    </message>
    <message>
        <source>%1 link %2 for specimen &apos;%3&apos; (%4)</source>
        <translation>%1 链路 %2，用于试件“%3”（%4）</translation>
    </message>
    <message>
        <source>prediction rejected: %1</source>
        <translation>预测被拒绝：%1</translation>
    </message>
    <message>
        <source>update rejected: %1</source>
        <translation>更新被拒绝：%1</translation>
    </message>
    <message>
        <source>Bouc-Wen integration failed (%1): %2</source>
        <translation>Bouc-Wen 积分失败（%1）：%2</translation>
    </message>
    <message>
        <source>%1; z and e could not be advanced either: step skipped</source>
        <translation>%1；z 和 e 也无法推进：跳过此步</translation>
    </message>
    <message>
        <source>the state is not finite</source>
        <translation>状态不是有限值</translation>
    </message>
    <message>
        <source>the measurement is not finite</source>
        <translation>测量值不是有限值</translation>
    </message>
    <message>
        <source>the predicted measurement is not finite</source>
        <translation>预测的测量值不是有限值</translation>
    </message>
    <message>
        <source>the innovation covariance is not positive definite (check R)</source>
        <translation>新息协方差不是正定的（请检查 R）</translation>
    </message>
    <message>
        <source>the filter has not been initialized</source>
        <translation>滤波器尚未初始化</translation>
    </message>
    <message>
        <source>Nelder-Mead fit failed: %1</source>
        <translation>Nelder-Mead 拟合失败：%1</translation>
    </message>
    <message>
        <source>Nelder-Mead trigger %1 kept the parameters (RMS %2 not improved, %3 evaluations, %4 ms)</source>
        <translation>Nelder-Mead 第 %1 次触发保留了参数（RMS %2 未改善，%3 次评估，%4 毫秒）</translation>
    </message>
    <message>
        <source>Nelder-Mead trigger %1: RMS force error %2 -&gt; %3 (%4 evaluations, %5 ms)</source>
        <translation>Nelder-Mead 第 %1 次触发：力的 RMS 误差 %2 -&gt; %3（%4 次评估，%5 毫秒）</translation>
    </message>
    <message>
        <source>the measured deformation or force is not finite: step skipped</source>
        <translation>测得的变形或力不是有限值：跳过此步</translation>
    </message>
    <message>
        <source>%1 line %2: %3</source>
        <translation>%1 第 %2 行：%3</translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos;: the file does not exist</source>
        <translation>无法打开“%1”：文件不存在</translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos;: it is a folder, not a file</source>
        <translation>无法打开“%1”：这是文件夹，不是文件</translation>
    </message>
    <message>
        <source>cannot read &apos;%1&apos;: not a regular file (a device, pipe or socket)</source>
        <translation>无法读取“%1”：不是普通文件（设备、管道或套接字）</translation>
    </message>
    <message>
        <source>cannot open &apos;%1&apos; for reading (permissions?)</source>
        <translation>无法打开“%1”进行读取（权限？）</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a text file (binary data at byte %2)</source>
        <translation>“%1”不是文本文件（第 %2 字节处为二进制数据）</translation>
    </message>
    <message>
        <source>the file is empty (expected a PEER AT2 record)</source>
        <translation>文件为空（应为 PEER AT2 记录）</translation>
    </message>
    <message>
        <source>the file is empty (no acceleration values)</source>
        <translation>文件为空（没有加速度值）</translation>
    </message>
    <message>
        <source>no data lines (only comments or blank lines)</source>
        <translation>没有数据行（只有注释或空行）</translation>
    </message>
    <message>
        <source>the file is empty: expected an AT2 header (&apos;NPTS=..., DT=...&apos; on line 4), two columns (time, acceleration) or one column of values</source>
        <translation>文件为空：应为 AT2 文件头（第 4 行为“NPTS=..., DT=...”）、两列（时间、加速度）或一列数值</translation>
    </message>
    <message>
        <source>no data lines: expected an AT2 header (&apos;NPTS=..., DT=...&apos; on line 4), two columns (time, acceleration) or one column of values</source>
        <translation>没有数据行：应为 AT2 文件头（第 4 行为“NPTS=..., DT=...”）、两列（时间、加速度）或一列数值</translation>
    </message>
    <message>
        <source>expected a number, found %1</source>
        <translation>应为数字，实际为 %1</translation>
    </message>
    <message>
        <source>non-finite value %1</source>
        <translation>非有限值 %1</translation>
    </message>
    <message>
        <source>the time step dt must be &gt; 0 s, got %1</source>
        <translation>时间步长 dt 必须 &gt; 0 秒，实际为 %1</translation>
    </message>
    <message>
        <source>expected two columns (time, acceleration), found %1 value(s)</source>
        <translation>应为两列（时间、加速度），实际有 %1 个值</translation>
    </message>
    <message>
        <source>only one sample: the time step cannot be determined</source>
        <translation>只有一个样本：无法确定时间步长</translation>
    </message>
    <message>
        <source>time must increase: %1 s follows %2 s</source>
        <translation>时间必须递增：%1 秒在 %2 秒之后</translation>
    </message>
    <message>
        <source>non-uniform time step: %1 s follows %2 s (step %3 s, mean step %4 s); a uniform step is required (tolerance 1e-6 relative)</source>
        <translation>时间步长不均匀：%1 秒在 %2 秒之后（步长 %3 秒，平均步长 %4 秒）；需要均匀步长（相对容差 1e-6）</translation>
    </message>
    <message>
        <source>a single column of acceleration values needs the time step dt, and none was given</source>
        <translation>单列加速度值需要时间步长 dt，但未给出</translation>
    </message>
    <message>
        <source>cannot open the configuration file</source>
        <translation>无法打开配置文件</translation>
    </message>
    <message>
        <source>not a regular file (a folder, device, pipe or socket)</source>
        <translation>不是普通文件（文件夹、设备、管道或套接字）</translation>
    </message>
    <message>
        <source>not valid JSON (%1)</source>
        <translation>不是有效的 JSON（%1）</translation>
    </message>
    <message>
        <source>cannot be opened (no such file)</source>
        <translation>无法打开（文件不存在）</translation>
    </message>
    <message>
        <source>not an HSMU record (not an HDF5 file)</source>
        <translation>不是 HSMU 记录（不是 HDF5 文件）</translation>
    </message>
    <message>
        <source>not an HSMU record (no schema_version attribute)</source>
        <translation>不是 HSMU 记录（没有 schema_version 属性）</translation>
    </message>
    <message>
        <source>damaged record (%1)</source>
        <translation>记录已损坏（%1）</translation>
    </message>
    <message>
        <source>ideal</source>
        <translation>理想</translation>
    </message>
    <message>
        <source>lag</source>
        <translation>一阶滞后</translation>
    </message>
    <message>
        <source>delay</source>
        <translation>纯延迟</translation>
    </message>
    <message>
        <source>fast</source>
        <translation>快速</translation>
    </message>
    <message>
        <source>real-time</source>
        <translation>实时</translation>
    </message>
    <message>
        <source>the record holds no step</source>
        <translation>记录中没有任何步</translation>
    </message>
    <message>
        <source>RTHS run held: %1</source>
        <translation>RTHS 试验已保持：%1</translation>
    </message>
    <message>
        <source>live delay J1 = %1 ms over the warning threshold %2 ms</source>
        <translation>实时延迟 J1 = %1 ms，超过警告阈值 %2 ms</translation>
    </message>
    <message>
        <source>live delay J1 = %1 ms over the critical threshold %2 ms</source>
        <translation>实时延迟 J1 = %1 ms，超过严重阈值 %2 ms</translation>
    </message>
    <message>
        <source>live tracking error J2 = %1 % over the warning threshold %2 %</source>
        <translation>实时跟踪误差 J2 = %1 %，超过警告阈值 %2 %</translation>
    </message>
    <message>
        <source>live tracking error J2 = %1 % over the critical threshold %2 %</source>
        <translation>实时跟踪误差 J2 = %1 %，超过严重阈值 %2 %</translation>
    </message>
    <message>
        <source>RTHS run not followed: %1</source>
        <translation>无法跟踪 RTHS 试验：%1</translation>
    </message>
</context>
<context>
    <name>CompareCommand</name>
    <message>
        <source>Run the paper&apos;s comparison protocol (reference, initial, updated).</source>
        <translation>运行论文中的对比方案（参考、初始、更新后）。</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>子命令。</translation>
    </message>
    <message>
        <source>Configuration file or preset name.</source>
        <translation>配置文件或预设名称。</translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation>输出目录。</translation>
    </message>
    <message>
        <source>Write PNG plots.</source>
        <translation>输出 PNG 图表。</translation>
    </message>
    <message>
        <source>Compared numerical element (default: the first updating target).</source>
        <translation>用于对比的数值单元（默认：第一个更新目标）。</translation>
    </message>
    <message>
        <source>Compared DOF (default: the element&apos;s DOF).</source>
        <translation>用于对比的自由度（默认：该单元的自由度）。</translation>
    </message>
    <message>
        <source>expected exactly one CONFIG (a file or a preset name)</source>
        <translation>应恰好给出一个 CONFIG（文件或预设名称）</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>缺少 --out DIR</translation>
    </message>
    <message>
        <source>%1 run %2/3: %3 %  (%4 s)</source>
        <translation>%1 试验 %2/3：%3 %  (%4 s)</translation>
    </message>
    <message>
        <source>%1: the configuration has no online model updating (an enabled &quot;updating&quot; section); compare needs one to run the updated test</source>
        <translation>%1：该配置未启用在线模型更新（需要启用的 &quot;updating&quot; 部分）；compare 需要它来运行更新后的试验</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1：无法创建输出目录</translation>
    </message>
    <message>
        <source>hsmu compare: three runs (reference, initial, updated) of %1</source>
        <translation>hsmu compare：%1 的三次试验（参考、初始、更新后）</translation>
    </message>
    <message>
        <source>%1: %2 steps, %3</source>
        <translation>%1：%2 步，%3</translation>
    </message>
    <message>
        <source>hsmu compare: the %1 run stopped at step %2 (state %3)%4</source>
        <translation>hsmu compare：%1 试验在第 %2 步停止（状态 %3）%4</translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation>%1：无法写出图表</translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation>  输出：%1</translation>
    </message>
    <message>
        <source>--plots: this program cannot draw (run it through hsmu)</source>
        <translation>--plots：此程序无法绘图（请通过 hsmu 运行）</translation>
    </message>
</context>
<context>
    <name>ComparisonPlotExporter</name>
    <message>
        <source>reference</source>
        <translation>参考</translation>
    </message>
    <message>
        <source>initial (not updated)</source>
        <translation>初始（未更新）</translation>
    </message>
    <message>
        <source>updated</source>
        <translation>更新后</translation>
    </message>
    <message>
        <source>Hysteresis of %1: reference, initial and updated</source>
        <translation>%1 的滞回曲线：参考、初始与更新后</translation>
    </message>
    <message>
        <source>Moment history of %1</source>
        <translation>%1 的弯矩时程</translation>
    </message>
    <message>
        <source>Force history of %1</source>
        <translation>%1 的力时程</translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation>弯矩 [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation>力 [%1]</translation>
    </message>
    <message>
        <source>Displacement of %1</source>
        <translation>%1 的位移</translation>
    </message>
    <message>
        <source>Displacement [m]</source>
        <translation>位移 [m]</translation>
    </message>
</context>
<context>
    <name>ComparisonTable</name>
    <message>
        <source>Comparison against the reference run: %1 force [%2], %3 displacement [m]</source>
        <translation>与参考试验的对比：%1 的力 [%2]，%3 的位移 [m]</translation>
    </message>
    <message>
        <source>run</source>
        <translation>试验</translation>
    </message>
    <message>
        <source>force NRMSE</source>
        <translation>力 NRMSE</translation>
    </message>
    <message>
        <source>force peak error [%1]</source>
        <translation>力峰值误差 [%1]</translation>
    </message>
    <message>
        <source>displ. NRMSE</source>
        <translation>位移 NRMSE</translation>
    </message>
    <message>
        <source>displ. peak error [m]</source>
        <translation>位移峰值误差 [m]</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>步数</translation>
    </message>
    <message>
        <source>initial</source>
        <translation>初始</translation>
    </message>
    <message>
        <source>updated</source>
        <translation>更新后</translation>
    </message>
    <message>
        <source>  initial / updated NRMSE: force %1x, displacement %2x</source>
        <translation>  NRMSE 初始 / 更新后之比：力 %1x，位移 %2x</translation>
    </message>
    <message>
        <source>Final parameters of the updated run (%1 updates applied):</source>
        <translation>更新后试验的最终参数（已应用 %1 次更新）：</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>std</source>
        <translation>标准差</translation>
    </message>
    <message>
        <source>true</source>
        <translation>真值</translation>
    </message>
    <message>
        <source>reference</source>
        <translation>参考</translation>
    </message>
    <message>
        <source>element</source>
        <translation>单元</translation>
    </message>
    <message>
        <source>basic DOF</source>
        <translation>基本自由度</translation>
    </message>
    <message>
        <source>deformation NRMSE</source>
        <translation>变形 NRMSE</translation>
    </message>
    <message>
        <source>deformation peak error</source>
        <translation>变形峰值误差</translation>
    </message>
    <message>
        <source>force peak error</source>
        <translation>力峰值误差</translation>
    </message>
    <message>
        <source>Per basic DOF against the reference run:</source>
        <translation>各基本自由度与参考试验的对比：</translation>
    </message>
    <message>
        <source>actuator</source>
        <translation>作动器</translation>
    </message>
    <message>
        <source>control</source>
        <translation>控制</translation>
    </message>
    <message>
        <source>force</source>
        <translation>力</translation>
    </message>
    <message>
        <source>displacement</source>
        <translation>位移</translation>
    </message>
    <message>
        <source>Per actuator: tracking against its command, force against the reference run:</source>
        <translation>各作动器：对其指令的跟踪，力与参考试验的对比：</translation>
    </message>
</context>
<context>
    <name>ConsoleCommand</name>
    <message>
        <source>The record&apos;s own sample step [s] (a one-column file of values needs it).</source>
        <translation>记录本身的采样步长 [s]（仅含一列数值的文件需要它）。</translation>
    </message>
    <message>
        <source>HSMU Console: hybrid simulation with online model updating.
Subcommands: run CONFIG --out DIR ..., compare CONFIG --out DIR ..., material --law ... (see hsmu run --help, hsmu compare --help, docs/cli.md).</source>
        <translation>HSMU Console：带在线模型更新的混合试验。
子命令：run CONFIG --out DIR ...，compare CONFIG --out DIR ...，material --law ...（参见 hsmu run --help、hsmu compare --help、docs/cli.md）。</translation>
    </message>
    <message>
        <source>Load a preset or configuration and start it.</source>
        <translation>加载预设或配置并启动试验。</translation>
    </message>
    <message>
        <source>Ground-motion record file.</source>
        <translation>地震动记录文件。</translation>
    </message>
    <message>
        <source>Test time per wall time (0: as fast as possible).</source>
        <translation>试验时间与实际时间之比（0：尽可能快）。</translation>
    </message>
    <message>
        <source>Grab the window into this PNG file, then quit.</source>
        <translation>将窗口截图保存到此 PNG 文件，然后退出。</translation>
    </message>
    <message>
        <source>Seconds before the screenshot (default 4).</source>
        <translation>截图前等待的秒数（默认 4）。</translation>
    </message>
    <message>
        <source>unknown subcommand &apos;%1&apos; (expected run, compare or material)</source>
        <translation>未知子命令“%1”（应为 run、compare 或 material）</translation>
    </message>
    <message>
        <source>--screenshot-after: expected a number of seconds</source>
        <translation>--screenshot-after：应为秒数</translation>
    </message>
    <message>
        <source>--speed: expected a number</source>
        <translation>--speed：应为数值</translation>
    </message>
    <message>
        <source>Actuator controller: builtin (the default) or tcp://HOST:PORT.</source>
        <translation>作动器控制器：builtin（默认）或 tcp://HOST:PORT。</translation>
    </message>
    <message>
        <source>--controller: %1</source>
        <translation>--controller：%1</translation>
    </message>
</context>
<context>
    <name>ExportCommand</name>
    <message>
        <source>Write a run record (HDF5) as CSV files, one per group.</source>
        <translation>将试验记录（HDF5）写为 CSV 文件，每组一个。</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>子命令。</translation>
    </message>
    <message>
        <source>The record (record.h5).</source>
        <translation>记录文件（record.h5）。</translation>
    </message>
    <message>
        <source>Output directory for the CSVs.</source>
        <translation>CSV 文件的输出目录。</translation>
    </message>
    <message>
        <source>expected exactly one FILE.h5</source>
        <translation>应恰好给出一个 FILE.h5</translation>
    </message>
    <message>
        <source>missing --csv DIR</source>
        <translation>缺少 --csv DIR</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1：无法创建输出目录</translation>
    </message>
    <message>
        <source>%1 steps, %2 alarms; written:</source>
        <translation>%1 步，%2 条报警；已写出：</translation>
    </message>
    <message>
        <source>Units of the CSV columns, e.g. length=in,force=kip,rotation=deg,moment=kip*in,time=ms (length: m, cm, mm, in, ft; force: N, kN, MN, lbf, kip, kgf, tonf; rotation: rad, mrad, deg; moment: a force unit times a length unit; time: s, ms). Default: kN, m, s, rad.</source>
        <translation>CSV 各列的单位，例如 length=in,force=kip,rotation=deg,moment=kip*in,time=ms（长度：m、cm、mm、in、ft；力：N、kN、MN、lbf、kip、kgf、tonf；转角：rad、mrad、deg；弯矩：力单位乘以长度单位；时间：s、ms）。默认：kN、m、s、rad。</translation>
    </message>
</context>
<context>
    <name>GroundMotionCheck</name>
    <message>
        <source>%1 is not a text file of numbers (it holds binary data, e.g. an image); expected a PEER AT2 record, two columns (time, acceleration) or one column of values</source>
        <translation>%1 不是数字文本文件（含二进制数据，例如图像）；应为 PEER AT2 记录、两列（时间、加速度）或一列数值</translation>
    </message>
</context>
<context>
    <name>MaterialCommand</name>
    <message>
        <source>Drive one hysteresis law with a deformation history.</source>
        <translation>用变形历程驱动一个滞回模型。</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>子命令。</translation>
    </message>
    <message>
        <source>Law: %1.</source>
        <translation>滞回模型：%1。</translation>
    </message>
    <message>
        <source>A law parameter (repeatable).</source>
        <translation>滞回模型参数（可重复指定）。</translation>
    </message>
    <message>
        <source>Deformation history (CSV or text).</source>
        <translation>变形历程（CSV 或文本）。</translation>
    </message>
    <message>
        <source>Output CSV (default: stdout).</source>
        <translation>输出 CSV（默认：stdout）。</translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>意外的参数“%1”</translation>
    </message>
    <message>
        <source>missing --law (one of %1)</source>
        <translation>缺少 --law（可选：%1）</translation>
    </message>
    <message>
        <source>missing --history FILE</source>
        <translation>缺少 --history FILE</translation>
    </message>
    <message>
        <source>--param &apos;%1&apos;: expected NAME=VALUE with a finite number</source>
        <translation>--param “%1”：应为 NAME=VALUE 形式，且 VALUE 为有限数值</translation>
    </message>
    <message>
        <source>Time step [s] between the points of a one-column history (a rate-dependent law).</source>
        <translation>单列历程中各点之间的时间步长 [s]（用于与速率相关的本构）。</translation>
    </message>
    <message>
        <source>--dt &apos;%1&apos;: expected a time step &gt; 0 in seconds</source>
        <translation>--dt &apos;%1&apos;：应为大于 0 的时间步长（秒）</translation>
    </message>
    <message>
        <source>--dt: the history has its own time column</source>
        <translation>--dt：该历程已有自己的时间列</translation>
    </message>
    <message>
        <source>%1 is rate-dependent: give the history a time column (time, deformation) or --dt</source>
        <translation>%1 与速率相关：请为历程提供时间列（时间, 变形）或 --dt</translation>
    </message>
</context>
<context>
    <name>MethodComparisonTable</name>
    <message>
        <source>Method comparison on %1: %2 samples</source>
        <translation>方法比较：%1，%2 个样本</translation>
    </message>
    <message>
        <source>method</source>
        <translation>方法</translation>
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
        <translation>位于边界</translation>
    </message>
    <message>
        <source>rejected</source>
        <translation>拒绝</translation>
    </message>
    <message>
        <source>verdict</source>
        <translation>结论</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>  recommended: %1 (the cheapest within 5 % of the best NRMSE)</source>
        <translation>  推荐：%1（NRMSE 在最佳值 5 % 以内的最省时方法）</translation>
    </message>
    <message>
        <source>  verdict: %1</source>
        <translation>  结论：%1</translation>
    </message>
    <message>
        <source>  outputs: %1 (comparison.csv, summary.json; each method&apos;s own files in calibration/, ukf/, nelder-mead/)</source>
        <translation>  输出：%1（comparison.csv、summary.json；各方法自己的文件在 calibration/、ukf/、nelder-mead/ 中）</translation>
    </message>
</context>
<context>
    <name>OperatorEvent</name>
    <message>
        <source>pre-flight confirmed by the operator (zero offsets)</source>
        <translation>操作员已确认试验前检查（零点）</translation>
    </message>
    <message>
        <source>test started by the operator</source>
        <translation>操作员已开始试验</translation>
    </message>
    <message>
        <source>paused by the operator</source>
        <translation>操作员已暂停</translation>
    </message>
    <message>
        <source>single step by the operator</source>
        <translation>操作员执行单步</translation>
    </message>
    <message>
        <source>resumed by the operator</source>
        <translation>操作员已继续</translation>
    </message>
    <message>
        <source>emergency hold before the test was armed: nothing is armed, the pre-flight check must be confirmed again</source>
        <translation>试验未就绪前的紧急保持：没有任何就绪项，必须重新确认试验前检查</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>操作员紧急保持</translation>
    </message>
    <message>
        <source>test ended by the operator, data kept</source>
        <translation>操作员已结束试验，数据已保留</translation>
    </message>
    <message>
        <source>update %1 approved by the operator: %2 -&gt; %3</source>
        <translation>操作员批准了更新 %1：%2 -&gt; %3</translation>
    </message>
    <message>
        <source>update %1 rejected by the operator (%2)</source>
        <translation>操作员拒绝了更新 %1（%2）</translation>
    </message>
    <message>
        <source>offsets %1 approved by the operator for %2: %3</source>
        <translation>操作员为 %2 批准了偏移 %1：%3</translation>
    </message>
    <message>
        <source>offsets %1 rejected by the operator (%2)</source>
        <translation>操作员拒绝了偏移 %1（%2）</translation>
    </message>
    <message>
        <source>bounds changed: %1 -&gt; %2</source>
        <translation>界限已更改：%1 -&gt; %2</translation>
    </message>
    <message>
        <source>lock changed: %1 -&gt; %2</source>
        <translation>锁定已更改：%1 -&gt; %2</translation>
    </message>
    <message>
        <source>fit-error threshold changed: %1 -&gt; %2</source>
        <translation>拟合误差阈值已更改：%1 -&gt; %2</translation>
    </message>
    <message>
        <source>updating policy changed: %1 -&gt; %2</source>
        <translation>更新策略已更改：%1 -&gt; %2</translation>
    </message>
    <message>
        <source>%1 (wall time %2)</source>
        <translation>%1（实际时间 %2）</translation>
    </message>
    <message>
        <source>pre-flight check skipped: the test was started from the command line (--start)</source>
        <translation>已跳过起飞前检查：试验由命令行启动（--start）</translation>
    </message>
    <message>
        <source>note recorded: %1</source>
        <translation>已记录备注：%1</translation>
    </message>
    <message>
        <source>%1 (%L2 committed steps, last deformation %3 %4)</source>
        <translation>%1（%L2 个已提交步，最后变形 %3 %4）</translation>
    </message>
    <message>
        <source>specimen loaded by an earlier test: %1; the operator continues on it</source>
        <translation>试件已被先前的试验加载：%1；操作员在其上继续</translation>
    </message>
    <message>
        <source>specimen loaded by an earlier test: %1; the operator chose a fresh specimen, its controller reset it to step 0</source>
        <translation>试件已被先前的试验加载：%1；操作员选择了新试件，其控制器已将其重置到第 0 步</translation>
    </message>
    <message>
        <source>specimen loaded by an earlier test: %1; the operator chose a fresh specimen, its controller refused (nothing changed)</source>
        <translation>试件已被先前的试验加载：%1；操作员选择了新试件，其控制器拒绝（未作任何更改）</translation>
    </message>
</context>
<context>
    <name>OverrideOptions</name>
    <message>
        <source>The record&apos;s own sample step [s] (a one-column file of values needs it).</source>
        <translation>记录本身的采样步长 [s]（仅含一列数值的文件需要它）。</translation>
    </message>
    <message>
        <source>Ground-motion record file.</source>
        <translation>地震动记录文件。</translation>
    </message>
    <message>
        <source>Ground-motion scale factor.</source>
        <translation>地震动缩放系数。</translation>
    </message>
    <message>
        <source>Integration step [s].</source>
        <translation>积分步长 [s]。</translation>
    </message>
    <message>
        <source>Test duration [s].</source>
        <translation>试验时长 [s]。</translation>
    </message>
    <message>
        <source>--%1: expected a %2 number, found &apos;%3&apos;</source>
        <translation>--%1：应为%2数值，实际为“%3”</translation>
    </message>
    <message>
        <source>positive</source>
        <translation>正</translation>
    </message>
</context>
<context>
    <name>PlotExporter</name>
    <message>
        <source>%1: unknown plot format &apos;%2&apos; (expected png, svg or pdf)</source>
        <translation>%1：未知的图表格式“%2”（应为 png、svg 或 pdf）</translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation>%1：无法写出图表</translation>
    </message>
</context>
<context>
    <name>PreflightChecks</name>
    <message>
        <source>time step dt [s]</source>
        <translation>时间步长 dt [s]</translation>
    </message>
    <message>
        <source>duration [s]</source>
        <translation>持续时间 [s]</translation>
    </message>
    <message>
        <source>ground motion</source>
        <translation>地震动</translation>
    </message>
    <message>
        <source>ground motion scale [-]</source>
        <translation>地震动缩放系数 [-]</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>积分器</translation>
    </message>
    <message>
        <source>controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>步数</translation>
    </message>
    <message>
        <source>PGA [m/s²]</source>
        <translation>PGA [m/s²]</translation>
    </message>
    <message>
        <source>Unusual step count: %L1 steps (more than %L2); check dt and the duration.</source>
        <translation>步数异常：%L1 步（超过 %L2）；请检查 dt 和持续时间。</translation>
    </message>
    <message>
        <source>Unusual PGA: %1 m/s² (above %2 m/s²); check the ground motion scale.</source>
        <translation>PGA 异常：%1 m/s²（超过 %2 m/s²）；请检查地震动缩放系数。</translation>
    </message>
    <message>
        <source>The ground motion is zero (PGA 0 m/s²).</source>
        <translation>地震动为零（PGA 0 m/s²）。</translation>
    </message>
    <message>
        <source>Very small time step: dt = %1 s.</source>
        <translation>时间步长很小：dt = %1 s。</translation>
    </message>
    <message>
        <source>Changed since the last run: %1 %2 -&gt; %3</source>
        <translation>自上次试验以来已更改：%1 %2 -&gt; %3</translation>
    </message>
</context>
<context>
    <name>PreflightDialog</name>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
</context>
<context>
    <name>ReplayCommand</name>
    <message>
        <source>Re-identify a recorded specimen, or imported measured data, offline.</source>
        <translation>离线重新识别已记录的试件或导入的实测数据。</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>子命令。</translation>
    </message>
    <message>
        <source>A run record (record.h5).</source>
        <translation>试验记录文件（record.h5）。</translation>
    </message>
    <message>
        <source>Re-run the identification headless.</source>
        <translation>以无界面方式重新运行参数识别。</translation>
    </message>
    <message>
        <source>JSON with &quot;model&quot; and/or &quot;updating&quot; settings to override.</source>
        <translation>用于覆盖 &quot;model&quot; 和/或 &quot;updating&quot; 设置的 JSON。</translation>
    </message>
    <message>
        <source>The recorded specimen to identify.</source>
        <translation>要识别的已记录试件。</translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation>输出目录。</translation>
    </message>
    <message>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>意外的参数“%1”</translation>
    </message>
    <message>
        <source>give either FILE.h5 or --import DATA.csv, not both</source>
        <translation>请给出 FILE.h5 或 --import DATA.csv，不能同时给出</translation>
    </message>
    <message>
        <source>expected FILE.h5 (a run record) or --import DATA.csv</source>
        <translation>应为 FILE.h5（试验记录）或 --import DATA.csv</translation>
    </message>
    <message>
        <source>--units applies to --import only (a record has its units)</source>
        <translation>--units 仅适用于 --import（记录自带单位）</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>缺少 --out DIR</translation>
    </message>
    <message>
        <source>%1 identification of %2: %3 samples, dt %4 s</source>
        <translation>%2 的 %1 识别：%3 个样本，dt %4 s</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>initial</source>
        <translation>初始</translation>
    </message>
    <message>
        <source>final</source>
        <translation>最终</translation>
    </message>
    <message>
        <source>std</source>
        <translation>标准差</translation>
    </message>
    <message>
        <source>online</source>
        <translation>在线</translation>
    </message>
    <message>
        <source>  Nelder-Mead fits accepted: %1</source>
        <translation>  已接受的 Nelder-Mead 拟合：%1</translation>
    </message>
    <message>
        <source>  estimator warnings: %1 (see summary.json)</source>
        <translation>  估计器警告：%1（见 summary.json）</translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation>  输出：%1</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1：无法创建输出目录</translation>
    </message>
    <message>
        <source>Measured data: CSV or text of time (or a sample index), deformation, force with units.</source>
        <translation>测量数据：含单位的时间（或样本序号）、变形、力的 CSV 或文本文件。</translation>
    </message>
    <message>
        <source>Units of the imported columns time,deformation,force, e.g. s,mm,kN (time: s, ms or step; deformation: m, cm, mm, in, ft, rad, mrad, deg; force: N, kN, MN, lbf, kip, kgf, tonf, g or a moment such as kN*m, kip*in).</source>
        <translation>导入列 时间,变形,力 的单位，例如 s,mm,kN（时间：s、ms 或 step；变形：m、cm、mm、in、ft、rad、mrad、deg；力：N、kN、MN、lbf、kip、kgf、tonf、g，或弯矩如 kN*m、kip*in）。</translation>
    </message>
    <message>
        <source>Positions (from 1) of the imported time, deformation and force columns, e.g. 1,2,3; other columns are ignored.</source>
        <translation>导入的时间、变形、力列的位置（从 1 开始），例如 1,2,3；其他列被忽略。</translation>
    </message>
    <message>
        <source>--columns applies to --import only</source>
        <translation>--columns 仅适用于 --import</translation>
    </message>
    <message>
        <source>  calibration over the whole history (%1 starts, %2 s): NRMSE %3 %</source>
        <translation>  整个历程上的标定（%1 个初始点，%2 s）：NRMSE %3 %</translation>
    </message>
    <message>
        <source>on its bound</source>
        <translation>位于边界</translation>
    </message>
    <message>
        <source>  verdict: %1</source>
        <translation>  结论：%1</translation>
    </message>
    <message>
        <source>uRef %1 %2, fRef %3 %4</source>
        <translation>uRef %1 %2, fRef %3 %4</translation>
    </message>
    <message>
        <source>  normalized units (x = u / uRef, f = F / fRef), final model&apos;s scales: %1</source>
        <translation>  归一化单位 (x = u / uRef, f = F / fRef)，最终模型的尺度：%1</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>  final model over the whole history: RMS force error %1 %2 (NRMSE %3 %; the initial model&apos;s %4 %)</source>
        <translation>  最终模型在整个历史上：力的 RMS 误差 %1 %2（NRMSE %3 %；初始模型为 %4 %）</translation>
    </message>
    <message>
        <source>  online model&apos;s prediction over the record (each sample with the estimate known before it): NRMSE %1 %</source>
        <translation>  在线模型对整个记录的预测（每个样本使用其之前已知的估计）：NRMSE %1 %</translation>
    </message>
    <message>
        <source>  warning: %1</source>
        <translation>  警告：%1</translation>
    </message>
    <message>
        <source>    in the same scales: %1</source>
        <translation>    尺度相同：%1</translation>
    </message>
    <message>
        <source>    in its own scales: %1 (its normalized values are not comparable with the table&apos;s above)</source>
        <translation>    采用其自身的尺度：%1（其归一化值与上表中的值不可比较）</translation>
    </message>
    <message>
        <source>The calibration&apos;s deformation and force offsets: auto (fitted when the data ask for them, the default), on or off.</source>
        <translation>标定的变形偏移与力偏移：auto（数据需要时拟合，默认）、on 或 off。</translation>
    </message>
    <message>
        <source>--offsets: expected auto, on or off, found &apos;%1&apos;</source>
        <translation>--offsets：应为 auto、on 或 off，实际为“%1”</translation>
    </message>
    <message>
        <source>    offsets fitted: NRMSE %1 % with them, %2 % without (criterion %3 &lt; 0 over %4 branches)</source>
        <translation>    已拟合偏移：含偏移 NRMSE %1 %，不含 %2 %（判据 %3 &lt; 0，共 %4 个分支）</translation>
    </message>
    <message>
        <source>    offsets not needed: NRMSE %1 % with them, %2 % without (criterion %3 &gt;= 0 over %4 branches)</source>
        <translation>    无需偏移：含偏移 NRMSE %1 %，不含 %2 %（判据 %3 &gt;= 0，共 %4 个分支）</translation>
    </message>
    <message>
        <source>hsmu replay: %1 / %2 samples, %3 refits, %4 rejected, %5 s elapsed, about %6 s left</source>
        <translation>hsmu replay：%1 / %2 个样本，%3 次重新拟合，%4 次拒绝，已用 %5 s，约剩 %6 s</translation>
    </message>
    <message>
        <source>hsmu replay: %1 (%2 s elapsed)</source>
        <translation>hsmu replay：%1（已用 %2 s）</translation>
    </message>
    <message>
        <source>calibrating over the whole history</source>
        <translation>正在对整个历史进行标定</translation>
    </message>
    <message>
        <source>final fit over the whole history</source>
        <translation>对整个历史进行最终拟合</translation>
    </message>
    <message>
        <source>ukf, nelder-mead, calibration (only the whole-history fit) or all (the three, compared in one table).</source>
        <translation>ukf、nelder-mead、calibration（仅对整个历程拟合）或 all（三者，在一张表中比较）。</translation>
    </message>
    <message>
        <source>hsmu replay: calibrating over the whole history (minimization %1 of %2, %3 s elapsed)</source>
        <translation>hsmu replay：正在对整个历程进行标定（第 %1 次最小化，共 %2 次，已用 %3 s）</translation>
    </message>
    <message>
        <source>%1 identification of %2 interrupted (%3) during the %4: %5 / %6 samples done, %7 refits, %8 rejected</source>
        <translation>%2 的 %1 识别在%4期间被中断（%3）：已完成 %5 / %6 个样本，%7 次重新拟合，%8 次拒绝</translation>
    </message>
    <message>
        <source>online pass</source>
        <translation>在线处理</translation>
    </message>
    <message>
        <source>calibration</source>
        <translation>标定</translation>
    </message>
    <message>
        <source>final fit</source>
        <translation>最终拟合</translation>
    </message>
    <message>
        <source>  no estimate yet</source>
        <translation>  尚无估计</translation>
    </message>
    <message>
        <source>  parameters after sample %1:</source>
        <translation>  第 %1 个样本后的参数：</translation>
    </message>
    <message>
        <source>  partial summary: %1</source>
        <translation>  部分摘要：%1</translation>
    </message>
</context>
<context>
    <name>ReplayExport</name>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1：无法写入（%2）</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>ReplayWindowCommand</name>
    <message>
        <source>Replay a recorded test (an HDF5 run record) in a window.</source>
        <translation>在窗口中回放已记录的试验（HDF5 试验记录）。</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>子命令。</translation>
    </message>
    <message>
        <source>The run record (record.h5).</source>
        <translation>试验记录文件（record.h5）。</translation>
    </message>
    <message>
        <source>Test seconds per wall second (default 1).</source>
        <translation>每秒实际时间对应的试验秒数（默认 1）。</translation>
    </message>
    <message>
        <source>Start playing at once.</source>
        <translation>立即开始播放。</translation>
    </message>
    <message>
        <source>Grab the window into this PNG file, then quit.</source>
        <translation>将窗口截图保存到此 PNG 文件，然后退出。</translation>
    </message>
    <message>
        <source>Seconds before the screenshot (default 3).</source>
        <translation>截图前等待的秒数（默认 3）。</translation>
    </message>
    <message>
        <source>expected one record file: hsmu replay FILE.h5</source>
        <translation>应给出一个记录文件：hsmu replay FILE.h5</translation>
    </message>
    <message>
        <source>--speed: expected a positive number</source>
        <translation>--speed：应为正数</translation>
    </message>
    <message>
        <source>--screenshot-after: expected a number of seconds</source>
        <translation>--screenshot-after：应为秒数</translation>
    </message>
</context>
<context>
    <name>RthsCommand</name>
    <message>
        <source>the controller did not resume the run: %1</source>
        <translation>控制器未继续该试验：%1</translation>
    </message>
    <message>
        <source>With --controller: resume the controller&apos;s held run from the tick where it held instead of starting one.</source>
        <translation>与 --controller 一起使用：从保持处的周期继续控制器上已保持的试验，而不是开始新的试验。</translation>
    </message>
    <message>
        <source>--resume needs --controller: it resumes the held run hsmu-controller keeps (a local run is resumed in the console&apos;s RTHS view)</source>
        <translation>--resume 需要 --controller：它继续 hsmu-controller 保留的已保持试验（本地试验在控制台的 RTHS 视图中继续）</translation>
    </message>
    <message>
        <source>Real-time hybrid simulation on the virtual lab&apos;s servo-hydraulic actuator.</source>
        <translation>在虚拟实验室的电液伺服作动器上进行实时混合试验。</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>子命令。</translation>
    </message>
    <message>
        <source>A configuration file or rths-benchmark-case-1 .. -4.</source>
        <translation>配置文件或 rths-benchmark-case-1 .. -4。</translation>
    </message>
    <message>
        <source>Output folder.</source>
        <translation>输出文件夹。</translation>
    </message>
    <message>
        <source>Ground-motion record (m/s^2 unless the configuration says).</source>
        <translation>地震动记录（除非配置另有说明，单位 m/s^2）。</translation>
    </message>
    <message>
        <source>Scale of the record.</source>
        <translation>记录的缩放系数。</translation>
    </message>
    <message>
        <source>Stop after T seconds.</source>
        <translation>T 秒后停止。</translation>
    </message>
    <message>
        <source>fast (simulated, default) or realtime (wall clock).</source>
        <translation>fast（模拟，默认）或 realtime（实际时钟）。</translation>
    </message>
    <message>
        <source>Run the loop&apos;s thread under SCHED_FIFO (with --pace realtime).</source>
        <translation>以 SCHED_FIFO 运行回路线程（配合 --pace realtime）。</translation>
    </message>
    <message>
        <source>default, none, lead, polynomial, feedforward or ats.</source>
        <translation>default、none、lead、polynomial、feedforward 或 ats。</translation>
    </message>
    <message>
        <source>Draw the plant from the benchmark&apos;s distributions with this seed.</source>
        <translation>用此种子从基准问题的分布中抽取被控对象。</translation>
    </message>
    <message>
        <source>With --pace realtime: busy-wait the last N microseconds before each release (default: a quarter of the period, at most 100; 0: sleep only).</source>
        <translation>配合 --pace realtime：在每次释放前的最后 N 微秒内忙等待（默认：周期的四分之一，最多 100；0：仅休眠）。</translation>
    </message>
    <message>
        <source>--spin-us: expected 0 up to the loop period (%1 us), got &apos;%2&apos;</source>
        <translation>--spin-us：应为 0 到环路周期（%1 us）之间，实际为 &apos;%2&apos;</translation>
    </message>
    <message>
        <source>Check this computer instead of running: release S seconds of empty ticks at the configuration&apos;s loop rate (with --realtime-priority and --spin-us as a run would) and report how late they come.</source>
        <translation>检查本机而不运行：以配置的环路频率释放 S 秒的空节拍（与运行时相同地使用 --realtime-priority 和 --spin-us），并报告它们的延迟。</translation>
    </message>
    <message>
        <source>--probe-host checks this computer: run it on the controller&apos;s computer without --controller</source>
        <translation>--probe-host 检查的是本机：请在控制器所在的计算机上不带 --controller 运行</translation>
    </message>
    <message>
        <source>--probe-host: expected seconds in (0, 3600], got &apos;%1&apos;</source>
        <translation>--probe-host：应为 (0, 3600] 内的秒数，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>hsmu rths: real-time priority not taken (%1); the probe ran at normal priority</source>
        <translation>hsmu rths：未获得实时优先级（%1）；探测以普通优先级运行</translation>
    </message>
    <message>
        <source>host probe at %1 Hz (spin %2 us%3): %4</source>
        <translation>主机探测，%1 Hz（忙等 %2 us%3）：%4</translation>
    </message>
    <message>
        <source>, SCHED_FIFO 80</source>
        <translation>，SCHED_FIFO 80</translation>
    </message>
    <message>
        <source>Sensor noise seed.</source>
        <translation>传感器噪声种子。</translation>
    </message>
    <message>
        <source>Sensors without noise.</source>
        <translation>传感器无噪声。</translation>
    </message>
    <message>
        <source>expected one CONFIG (a file or rths-benchmark-case-1 .. -4)</source>
        <translation>需要一个 CONFIG（文件或 rths-benchmark-case-1 .. -4）</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>缺少 --out DIR</translation>
    </message>
    <message>
        <source>--pace: expected fast or realtime, got &apos;%1&apos;</source>
        <translation>--pace：应为 fast 或 realtime，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--compensation: expected default, none, lead, polynomial, feedforward or ats, got &apos;%1&apos;</source>
        <translation>--compensation：应为 default、none、lead、polynomial、feedforward 或 ats，实际为 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--seed, --scale and --duration take numbers</source>
        <translation>--seed、--scale 和 --duration 需要数字</translation>
    </message>
    <message>
        <source>--perturb takes a seed</source>
        <translation>--perturb 需要一个种子</translation>
    </message>
    <message>
        <source>no ground motion: give --ground-motion FILE</source>
        <translation>没有地震动：请给出 --ground-motion FILE</translation>
    </message>
    <message>
        <source>%1: the ground-motion record does not exist (give --ground-motion FILE)</source>
        <translation>%1：地震动记录不存在（请给出 --ground-motion FILE）</translation>
    </message>
    <message>
        <source>%1: %2 Hz loop, compensation %3%4</source>
        <translation>%1：%2 Hz 回路，补偿 %3%4</translation>
    </message>
    <message>
        <source> + phase lead</source>
        <translation> + 相位超前</translation>
    </message>
    <message>
        <source>pre-flight: %1</source>
        <translation>试验前检查：%1</translation>
    </message>
    <message>
        <source>refused in pre-flight: %1</source>
        <translation>试验前检查拒绝：%1</translation>
    </message>
    <message>
        <source>%1: cannot create the output folder</source>
        <translation>%1：无法创建输出文件夹</translation>
    </message>
    <message>
        <source>hsmu rths: real-time priority not taken (%1); the loop ran at normal priority</source>
        <translation>hsmu rths：未获得实时优先级（%1）；回路以普通优先级运行</translation>
    </message>
    <message>
        <source>%1 ticks (%2 s); %3</source>
        <translation>%1 个周期（%2 s）；%3</translation>
    </message>
    <message>
        <source>frequency evaluation: amplitude %1, delay %2 ms at %3 Hz; tracking indicator %4 m^2</source>
        <translation>频域评价：幅值 %1，延迟 %2 ms（%3 Hz）；跟踪指标 %4 m^2</translation>
    </message>
    <message>
        <source>deadline misses: %1 (worst %2 us late)</source>
        <translation>错过截止时间：%1 次（最差迟到 %2 us）</translation>
    </message>
    <message>
        <source>outputs: %1/record.h5, %1/steps.csv, %1/summary.json</source>
        <translation>输出：%1/record.h5、%1/steps.csv、%1/summary.json</translation>
    </message>
    <message>
        <source>hsmu rths: %1</source>
        <translation>hsmu rths：%1</translation>
    </message>
    <message>
        <source>Monitor the loop run by hsmu-controller --rths at tcp://HOST:PORT.</source>
        <translation>监视 hsmu-controller --rths 在 tcp://HOST:PORT 上运行的回路。</translation>
    </message>
    <message>
        <source>File whose first line is the controller&apos;s shared secret.</source>
        <translation>文件，其第一行为控制器的共享密钥。</translation>
    </message>
    <message>
        <source>With --controller: one telemetry frame every N ticks (default: about 128 per second).</source>
        <translation>与 --controller 一起使用：每 N 个周期一帧遥测数据（默认：约每秒 128 帧）。</translation>
    </message>
    <message>
        <source>--%1 does not apply with --controller: the controller runs the loop of its own copy of the configuration</source>
        <translation>--%1 不适用于 --controller：控制器按其自己的配置副本运行回路</translation>
    </message>
    <message>
        <source>--controller: %1</source>
        <translation>--controller：%1</translation>
    </message>
    <message>
        <source>--controller: an RTHS loop is monitored over tcp://HOST:PORT (hsmu-controller --rths)</source>
        <translation>--controller：RTHS 回路通过 tcp://HOST:PORT 监视（hsmu-controller --rths）</translation>
    </message>
    <message>
        <source>--token-file: %1</source>
        <translation>--token-file：%1</translation>
    </message>
    <message>
        <source>--telemetry-every: expected a whole number &gt;= 1, got &apos;%1&apos;</source>
        <translation>--telemetry-every：应为 &gt;= 1 的整数，得到 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>With --controller: at T seconds of the run, send new values of the damper twin&apos;s parameters (repeatable).</source>
        <translation>与 --controller 一起使用：在试验的第 T 秒发送阻尼器孪生模型参数的新值（可重复）。</translation>
    </message>
    <message>
        <source>--update: expected T:NAME=VALUE[,NAME=VALUE...] (seconds, then the damper twin&apos;s parameters), got &apos;%1&apos;</source>
        <translation>--update：应为 T:名称=值[,名称=值...]（秒，然后是阻尼器孪生模型的参数），得到 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--update needs --controller: it sends the update to the loop hsmu-controller runs</source>
        <translation>--update 需要 --controller：它把更新发送给 hsmu-controller 运行的回路</translation>
    </message>
    <message>
        <source>%1/telemetry.csv: cannot be written</source>
        <translation>%1/telemetry.csv：无法写入</translation>
    </message>
    <message>
        <source>cannot reach the controller %1:%2: %3</source>
        <translation>无法连接控制器 %1:%2：%3</translation>
    </message>
    <message>
        <source>the controller refused the monitor: %1</source>
        <translation>控制器拒绝了监视端：%1</translation>
    </message>
    <message>
        <source>controller: %1</source>
        <translation>控制器：%1</translation>
    </message>
    <message>
        <source>the link to the controller was lost: %1 (the controller holds the loop per its --monitor-loss policy); %2 telemetry frames in %3/telemetry.csv</source>
        <translation>与控制器的连接已断开：%1（控制器按其 --monitor-loss 策略保持回路）；%2 帧遥测数据在 %3/telemetry.csv 中</translation>
    </message>
    <message>
        <source>t = %1 s: desired %2 mm, measured %3 mm, %4 deadline misses</source>
        <translation>t = %1 s：期望 %2 mm，测量 %3 mm，%4 次错过截止时间</translation>
    </message>
    <message>
        <source>the controller: %1</source>
        <translation>控制器：%1</translation>
    </message>
    <message>
        <source>%1 ticks on the controller; %2</source>
        <translation>控制器上 %1 个周期；%2</translation>
    </message>
    <message>
        <source>deadline misses: %1 (worst %2 us late); telemetry %3 received, %4 dropped</source>
        <translation>错过截止时间：%1 次（最差延迟 %2 us）；遥测：收到 %3 帧，丢弃 %4 帧</translation>
    </message>
    <message>
        <source>outputs: %1/telemetry.csv, %1/summary.json</source>
        <translation>输出：%1/telemetry.csv，%1/summary.json</translation>
    </message>
</context>
<context>
    <name>RunCommand</name>
    <message>
        <source>%1 %  t = %2 s  %3 steps/s</source>
        <translation>%1 %  t = %2 s  %3 步/s</translation>
    </message>
    <message>
        <source>hsmu run: --approval ignored: the configuration has no updating</source>
        <translation>hsmu run：已忽略 --approval：该配置未启用模型更新</translation>
    </message>
    <message>
        <source>%1: cannot create the output directory</source>
        <translation>%1：无法创建输出目录</translation>
    </message>
    <message>
        <source>the test cannot start: %1</source>
        <translation>试验无法启动：%1</translation>
    </message>
    <message>
        <source>hsmu run: test held at t = %1 s (step %2): %3</source>
        <translation>hsmu run：试验在 t = %1 s（第 %2 步）时保持：%3</translation>
    </message>
    <message>
        <source>hsmu run: the test stopped unexpectedly (state %1)</source>
        <translation>hsmu run：试验意外停止（状态 %1）</translation>
    </message>
    <message>
        <source>%1: write failed</source>
        <translation>%1：写入失败</translation>
    </message>
    <message>
        <source>%1: the plot could not be written</source>
        <translation>%1：无法写出图表</translation>
    </message>
    <message>
        <source>hsmu run: connecting to %1 (%2 protocol, %3)</source>
        <translation>hsmu run：正在连接 %1（%2 协议，%3）</translation>
    </message>
    <message>
        <source>hsmu run: steps.csv not written (%1 columns); record.h5 holds every column (hsmu export writes CSV from it)</source>
        <translation>hsmu run：未写入 steps.csv（%1 列）；record.h5 保存所有列（hsmu export 可由其导出 CSV）</translation>
    </message>
    <message>
        <source>hsmu run: link fault at t = %1 s (step %2): %3; reconnecting in %4 s (attempt %5 of %6)</source>
        <translation>hsmu run：t = %1 s（第 %2 步）链路故障：%3；%4 s 后重新连接（第 %5 次，共 %6 次）</translation>
    </message>
    <message>
        <source>--plots: this program cannot draw (run it through hsmu)</source>
        <translation>--plots：此程序无法绘图（请通过 hsmu 运行）</translation>
    </message>
</context>
<context>
    <name>RunOptions</name>
    <message>
        <source>Run a hybrid test headless.</source>
        <translation>以无界面方式运行混合试验。</translation>
    </message>
    <message>
        <source>The subcommand.</source>
        <translation>子命令。</translation>
    </message>
    <message>
        <source>Configuration file or preset name.</source>
        <translation>配置文件或预设名称。</translation>
    </message>
    <message>
        <source>Output directory.</source>
        <translation>输出目录。</translation>
    </message>
    <message>
        <source>Run an explicit scheme past its stability limit.</source>
        <translation>允许显式积分格式超出其稳定极限运行。</translation>
    </message>
    <message>
        <source>Write PNG plots.</source>
        <translation>输出 PNG 图表。</translation>
    </message>
    <message>
        <source>File whose first line is the controller&apos;s shared secret (readable by you only; else the environment variable HSMU_CONTROLLER_TOKEN).</source>
        <translation>首行为与控制器共享密钥的文件（仅限本人可读；否则使用环境变量 HSMU_CONTROLLER_TOKEN）。</translation>
    </message>
    <message>
        <source>--token is not accepted: arguments show in ps; put the token in a file (--token-file FILE) or in the environment variable HSMU_CONTROLLER_TOKEN</source>
        <translation>不接受 --token：命令行参数在 ps 中可见；请将令牌放入文件（--token-file 文件）或环境变量 HSMU_CONTROLLER_TOKEN</translation>
    </message>
    <message>
        <source>--token-file: %1</source>
        <translation>--token-file：%1</translation>
    </message>
    <message>
        <source>After a lost link or a timeout, resume (and reconnect) up to N times before giving up (default 0: hold and exit 2).</source>
        <translation>链路中断或超时后，最多恢复（并重新连接）N 次，之后放弃（默认 0：保持并以代码 2 退出）。</translation>
    </message>
    <message>
        <source>Decision on update proposals of the onApproval policy: manual, approveAll or rejectAll (default: the configuration&apos;s).</source>
        <translation>onApproval 策略下对更新提议的处理方式：manual、approveAll 或 rejectAll（默认：采用配置中的设定）。</translation>
    </message>
    <message>
        <source>expected exactly one CONFIG (a file or a preset name)</source>
        <translation>应恰好给出一个 CONFIG（文件或预设名称）</translation>
    </message>
    <message>
        <source>missing --out DIR</source>
        <translation>缺少 --out DIR</translation>
    </message>
    <message>
        <source>--controller: %1</source>
        <translation>--controller：%1</translation>
    </message>
    <message>
        <source>--reconnect: expected a whole number &gt;= 0, found &apos;%1&apos;</source>
        <translation>--reconnect：应为 &gt;= 0 的整数，实际为“%1”</translation>
    </message>
    <message>
        <source>--approval: expected manual, approveAll or rejectAll, found &apos;%1&apos;</source>
        <translation>--approval：应为 manual、approveAll 或 rejectAll，实际为“%1”</translation>
    </message>
    <message>
        <source>Actuator controller: builtin (in-process virtual specimens, the default), tcp://HOST:PORT (hsmu-controller or a lab controller, in the configuration&apos;s controller.protocol, native by default), simapp://HOST:PORT (an OpenFresco SimApp server) or generictcp://HOST:PORT (a server for OpenFresco&apos;s GenericTCP).</source>
        <translation>作动器控制器：builtin（进程内虚拟试件，默认）、tcp://HOST:PORT（hsmu-controller 或实验室控制器，使用配置中的 controller.protocol，默认为 native）、simapp://HOST:PORT（OpenFresco SimApp 服务器）或 generictcp://HOST:PORT（供 OpenFresco GenericTCP 使用的服务器）。</translation>
    </message>
    <message>
        <source>steps.csv: auto (written when a row has at most 200 values, the default), all or none; record.h5 holds every column either way.</source>
        <translation>steps.csv：auto（每行最多 200 个值时写出，默认）、all 或 none；无论哪种，record.h5 都保存所有列。</translation>
    </message>
    <message>
        <source>Compress the record&apos;s per-step matrices: deflate level 1-9 with shuffle (default 0: uncompressed).</source>
        <translation>压缩记录的逐步矩阵：deflate 级别 1-9，带 shuffle（默认 0：不压缩）。</translation>
    </message>
    <message>
        <source>--csv: expected auto, all or none, found &apos;%1&apos;</source>
        <translation>--csv：应为 auto、all 或 none，实际为“%1”</translation>
    </message>
    <message>
        <source>--compress: expected a whole number from 0 to 9, found &apos;%1&apos;</source>
        <translation>--compress：应为 0 到 9 的整数，实际为“%1”</translation>
    </message>
    <message>
        <source>Numerical DOFs the record keeps: indices, ranges and names, e.g. 0-9,100,Roof (default: every DOF). A specimen&apos;s channels are always recorded in full.</source>
        <translation>记录保存的数值自由度：索引、范围和名称，例如 0-9,100,Roof（默认：全部自由度）。试件的通道总是完整记录。</translation>
    </message>
    <message>
        <source>Keep the numerical DOFs&apos; rows of every N-th step only (default 1). A specimen&apos;s channels are always recorded at every step.</source>
        <translation>数值自由度的行仅每 N 步保存一次（默认 1）。试件的通道总是每步记录。</translation>
    </message>
    <message>
        <source>--record-every: expected a whole number from 1 to %1, found &apos;%2&apos;</source>
        <translation>--record-every：应为 1 到 %1 的整数，实际为“%2”</translation>
    </message>
</context>
<context>
    <name>RunReport</name>
    <message>
        <source>  identified parameters of %1 (%2, final value ± std):</source>
        <translation>  %1 的识别参数（%2，最终值 ± 标准差）：</translation>
    </message>
    <message>
        <source>  updates applied: %1, proposals pending: %2, final fit error: %3</source>
        <translation>  已应用更新：%1，待处理提议：%2，最终拟合误差：%3</translation>
    </message>
    <message>
        <source>Test: %1</source>
        <translation>试验：%1</translation>
    </message>
    <message>
        <source>  state: %1, steps: %2 of %3, test time: %4 s, wall time: %5 s</source>
        <translation>  状态：%1，步数：%2 / %3，试验时间：%4 s，实际耗时：%5 s</translation>
    </message>
    <message>
        <source>  peak displacement:</source>
        <translation>  峰值位移：</translation>
    </message>
    <message>
        <source>  peak force:</source>
        <translation>  峰值力：</translation>
    </message>
    <message>
        <source>  tracking of %1 (commanded against measured): J1 %2 ms, J2 %3 %, J3 %4 %</source>
        <translation>  %1 的跟踪（指令对比实测）：J1 %2 ms，J2 %3 %，J3 %4 %</translation>
    </message>
    <message>
        <source>  alarms: none</source>
        <translation>  报警：无</translation>
    </message>
    <message>
        <source>  alarms:</source>
        <translation>  报警：</translation>
    </message>
    <message>
        <source>  outputs: %1</source>
        <translation>  输出：%1</translation>
    </message>
    <message>
        <source>  record: DOFs %1 (%2 of %3), every %4 steps; elements, specimens and updating at every step</source>
        <translation>  记录：自由度 %1（%3 个中的 %2 个），每 %4 步；单元、试件和更新每步记录</translation>
    </message>
    <message>
        <source>... %1 more in summary.json</source>
        <translation>……另有 %1 项见 summary.json</translation>
    </message>
</context>
<context>
    <name>RunState</name>
    <message>
        <source>no test loaded</source>
        <translation>未加载试验</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>就绪</translation>
    </message>
    <message>
        <source>running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>paused</source>
        <translation>已暂停</translation>
    </message>
    <message>
        <source>holding</source>
        <translation>保持中</translation>
    </message>
    <message>
        <source>finished</source>
        <translation>已完成</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>失败</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ActuatorsPanel</name>
    <message>
        <source>Displacement [%1]</source>
        <translation>位移 [%1]</translation>
    </message>
    <message>
        <source>Rotation [%1]</source>
        <translation>转角 [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation>力 [%1]</translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation>弯矩 [%1]</translation>
    </message>
    <message>
        <source>axial</source>
        <translation>轴向</translation>
    </message>
    <message>
        <source>shear</source>
        <translation>剪切</translation>
    </message>
    <message>
        <source>rotation</source>
        <translation>转动</translation>
    </message>
    <message>
        <source>commanded</source>
        <translation>指令</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>实测</translation>
    </message>
    <message>
        <source>command</source>
        <translation>指令值</translation>
    </message>
    <message>
        <source>stroke</source>
        <translation>行程</translation>
    </message>
    <message>
        <source>force</source>
        <translation>力</translation>
    </message>
    <message>
        <source>%1: %2 DOF</source>
        <translation>%1：%2 自由度</translation>
    </message>
    <message>
        <source>%1: actuator &apos;%2&apos;</source>
        <translation>%1：作动器“%2”</translation>
    </message>
    <message>
        <source>%1: every basic deformation</source>
        <translation>%1：全部基本变形</translation>
    </message>
    <message>
        <source>%1: every basic force</source>
        <translation>%1：全部基本力</translation>
    </message>
    <message>
        <source>%1: every actuator&apos;s stroke</source>
        <translation>%1：各作动器行程</translation>
    </message>
    <message>
        <source>%1: every actuator&apos;s force</source>
        <translation>%1：各作动器力</translation>
    </message>
    <message>
        <source>The actuator, basic DOF or set of channels the plot shows</source>
        <translation>图中显示的作动器、基本自由度或通道组</translation>
    </message>
    <message>
        <source>No step yet.</source>
        <translation>尚无步。</translation>
    </message>
    <message>
        <source>Step %1, t = %2 s: %3</source>
        <translation>第 %1 步，t = %2 s：%3</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::AlarmList</name>
    <message>
        <source>limit exceeded</source>
        <translation>超限</translation>
    </message>
    <message>
        <source>control fault</source>
        <translation>控制故障</translation>
    </message>
    <message>
        <source>element fault</source>
        <translation>单元故障</translation>
    </message>
    <message>
        <source>integrator fault</source>
        <translation>积分器故障</translation>
    </message>
    <message>
        <source>operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <source>stability</source>
        <translation>稳定性</translation>
    </message>
    <message>
        <source>model fit error</source>
        <translation>模型拟合误差</translation>
    </message>
    <message>
        <source>fracture</source>
        <translation>断裂</translation>
    </message>
    <message>
        <source>estimator rejected</source>
        <translation>估计器拒绝</translation>
    </message>
    <message>
        <source>parameter at a bound</source>
        <translation>参数达到边界</translation>
    </message>
    <message>
        <source>actuator tracking</source>
        <translation>作动器跟踪</translation>
    </message>
    <message>
        <source>model update</source>
        <translation>模型更新</translation>
    </message>
    <message>
        <source>info</source>
        <translation>信息</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>critical</source>
        <translation>严重</translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>步</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>严重程度</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>消息</translation>
    </message>
    <message>
        <source>Acknowledged</source>
        <translation>已确认</translation>
    </message>
    <message>
        <source>console</source>
        <translation>控制台</translation>
    </message>
    <message>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <source>yes, %1</source>
        <translation>是，%1</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1：无法写入（%2）</translation>
    </message>
    <message>
        <source>Copy the list</source>
        <translation>复制列表</translation>
    </message>
    <message>
        <source>Copy selected rows</source>
        <translation>复制所选行</translation>
    </message>
    <message>
        <source>Export the list as CSV...</source>
        <translation>将列表导出为 CSV...</translation>
    </message>
    <message>
        <source>Export alarms and events</source>
        <translation>导出报警和事件</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::AlarmPanel</name>
    <message>
        <source>Acknowledge selected</source>
        <translation>确认所选</translation>
    </message>
    <message>
        <source>Acknowledge all</source>
        <translation>全部确认</translation>
    </message>
    <message>
        <source>Critical alarms stay red until acknowledged (double-click or the buttons).</source>
        <translation>严重报警在确认前保持红色（双击或使用按钮确认）。</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::AttentionBanner</name>
    <message>
        <source>Acknowledge all</source>
        <translation>全部确认</translation>
    </message>
    <message numerus="yes">
        <source>%n critical alarm(s) not acknowledged. Latest: %1</source>
        <translation>
            <numerusform>%n 条严重报警未确认。最新：%1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ControlBar</name>
    <message>
        <source>Test control</source>
        <translation>试验控制</translation>
    </message>
    <message>
        <source>Preset: </source>
        <translation>预设: </translation>
    </message>
    <message>
        <source>Test configurations shipped with the console</source>
        <translation>控制台自带的试验配置</translation>
    </message>
    <message>
        <source>(choose a preset)</source>
        <translation>（选择预设）</translation>
    </message>
    <message>
        <source>Open configuration...</source>
        <translation>打开配置...</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>启动</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source> Speed: </source>
        <translation> 速度: </translation>
    </message>
    <message>
        <source>Test time per wall-clock time</source>
        <translation>试验时间与实际时间之比</translation>
    </message>
    <message>
        <source>0.5 x real time</source>
        <translation>0.5 倍实时</translation>
    </message>
    <message>
        <source>real time</source>
        <translation>实时</translation>
    </message>
    <message>
        <source>2 x real time</source>
        <translation>2 倍实时</translation>
    </message>
    <message>
        <source>5 x real time</source>
        <translation>5 倍实时</translation>
    </message>
    <message>
        <source>as fast as possible</source>
        <translation>尽可能快</translation>
    </message>
    <message>
        <source>Single step</source>
        <translation>单步</translation>
    </message>
    <message>
        <source>Emergency hold (%1)</source>
        <translation>紧急保持（%1）</translation>
    </message>
    <message>
        <source>Hold the test at once, between two steps (%1)</source>
        <translation>在两步之间立即保持试验（%1）</translation>
    </message>
    <message>
        <source>Stop...</source>
        <translation>停止...</translation>
    </message>
    <message>
        <source>1/%1 x real time</source>
        <translation>1/%1 倍实时</translation>
    </message>
    <message>
        <source>fixed wall time per step</source>
        <translation>每步固定实际时间</translation>
    </message>
    <message>
        <source>Each step takes this long in wall time (pseudo-dynamic pace)</source>
        <translation>每一步占用这么长的实际时间（拟动力速度）</translation>
    </message>
    <message>
        <source> s/step</source>
        <translation> 秒/步</translation>
    </message>
    <message>
        <source>Start the test after the pre-flight check (%1)</source>
        <translation>起飞前检查后开始试验（%1）</translation>
    </message>
    <message>
        <source>Pause between two steps (%1)</source>
        <translation>在两步之间暂停（%1）</translation>
    </message>
    <message>
        <source>Run exactly one integration step, then stay paused (%1)</source>
        <translation>只执行一个积分步，然后保持暂停（%1）</translation>
    </message>
    <message>
        <source>Continue the test (%1)</source>
        <translation>继续试验（%1）</translation>
    </message>
    <message>
        <source>End the test, keeping the data (asks for confirmation; %1)</source>
        <translation>结束试验并保留数据（需确认；%1）</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::HistoryPlot</name>
    <message>
        <source>Time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <source>Displacement history</source>
        <translation>位移时程</translation>
    </message>
    <message>
        <source>Displacement [m]</source>
        <translation>位移 [m]</translation>
    </message>
    <message>
        <source>Ground motion</source>
        <translation>地震动</translation>
    </message>
    <message>
        <source>Ground acceleration [m/s²]</source>
        <translation>地面加速度 [m/s²]</translation>
    </message>
    <message>
        <source>Ground acceleration</source>
        <translation>地面加速度</translation>
    </message>
    <message>
        <source>Force history</source>
        <translation>力时程</translation>
    </message>
    <message>
        <source>Moment history</source>
        <translation>弯矩时程</translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation>弯矩 [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation>力 [%1]</translation>
    </message>
    <message>
        <source>Tracking of %1</source>
        <translation>%1 的跟踪</translation>
    </message>
    <message>
        <source>Rotation [%1]</source>
        <translation>转角 [%1]</translation>
    </message>
    <message>
        <source>Deformation [%1]</source>
        <translation>变形 [%1]</translation>
    </message>
    <message>
        <source>commanded</source>
        <translation>指令值</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>实测值</translation>
    </message>
    <message>
        <source>Inspector fit error</source>
        <translation>检查器拟合误差</translation>
    </message>
    <message>
        <source>Fit error [-]</source>
        <translation>拟合误差 [-]</translation>
    </message>
    <message>
        <source>fit error</source>
        <translation>拟合误差</translation>
    </message>
    <message>
        <source>actuator command</source>
        <translation>作动器指令</translation>
    </message>
    <message>
        <source>held ticks</source>
        <translation>保持节拍数</translation>
    </message>
    <message>
        <source>Held ticks [-]</source>
        <translation>保持节拍数 [-]</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::HysteresisPlot</name>
    <message>
        <source>%1 (specimen, measured)</source>
        <translation>%1（试件，实测）</translation>
    </message>
    <message>
        <source>%1 (numerical)</source>
        <translation>%1（数值）</translation>
    </message>
    <message>
        <source>Hysteresis of %1</source>
        <translation>%1 的滞回曲线</translation>
    </message>
    <message>
        <source>Rotation [%1]</source>
        <translation>转角 [%1]</translation>
    </message>
    <message>
        <source>Deformation [%1]</source>
        <translation>变形 [%1]</translation>
    </message>
    <message>
        <source>Moment [%1]</source>
        <translation>弯矩 [%1]</translation>
    </message>
    <message>
        <source>Force [%1]</source>
        <translation>力 [%1]</translation>
    </message>
    <message>
        <source>auxiliary model (%1)</source>
        <translation>辅助模型（%1）</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::LivePlotsPanel</name>
    <message>
        <source>Dashed: %1</source>
        <translation>虚线：%1</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <source>SVG drawing (*.svg)</source>
        <translation>SVG 矢量图 (*.svg)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <source>Export this plot...</source>
        <translation>导出此图表...</translation>
    </message>
    <message>
        <source>Export all plots...</source>
        <translation>导出所有图表...</translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation>导出图表</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>导出失败</translation>
    </message>
    <message>
        <source>Export all plots to</source>
        <translation>将所有图表导出到</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::MainWindow</name>
    <message>
        <source>Enter the record&apos;s sample step below the file.</source>
        <translation>请在文件下方输入记录的采样步长。</translation>
    </message>
    <message>
        <source>HSMU Console</source>
        <translation>HSMU Console</translation>
    </message>
    <message>
        <source>Alarms and events</source>
        <translation>报警与事件</translation>
    </message>
    <message>
        <source>cannot load %1: %2</source>
        <translation>无法加载 %1：%2</translation>
    </message>
    <message>
        <source>Open configuration</source>
        <translation>打开配置</translation>
    </message>
    <message>
        <source>Test configurations (*.json);;All files (*)</source>
        <translation>试验配置 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Configuration error</source>
        <translation>配置错误</translation>
    </message>
    <message>
        <source>loaded %1 (%2)</source>
        <translation>已加载 %1（%2）</translation>
    </message>
    <message>
        <source>HSMU Console - %1</source>
        <translation>HSMU Console - %1</translation>
    </message>
    <message>
        <source>the test cannot start: %1</source>
        <translation>试验无法启动：%1</translation>
    </message>
    <message>
        <source>Test setup</source>
        <translation>试验设置</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Pending updates</source>
        <translation>待处理更新</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Open configuration...</source>
        <translation>打开配置(&amp;O)...</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <source>Open r&amp;ecord...</source>
        <translation>打开记录(&amp;E)...</translation>
    </message>
    <message>
        <source>&amp;Settings...</source>
        <translation>设置(&amp;S)...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>setup not applied: %1</source>
        <translation>设置未应用：%1</translation>
    </message>
    <message>
        <source>preparing the test (pre-flight)...</source>
        <translation>正在准备试验（预检）...</translation>
    </message>
    <message>
        <source>start cancelled at the pre-flight check</source>
        <translation>启动已在预检时取消</translation>
    </message>
    <message>
        <source>Add &amp;note...</source>
        <translation>添加备注(&amp;N)...</translation>
    </message>
    <message>
        <source>Record a note at the current step of the test</source>
        <translation>在试验的当前步记录一条备注</translation>
    </message>
    <message>
        <source>Add note</source>
        <translation>添加备注</translation>
    </message>
    <message>
        <source>Load and start a test first.</source>
        <translation>请先加载并启动试验。</translation>
    </message>
    <message>
        <source>Note (recorded with the current step and test time):</source>
        <translation>备注（连同当前步和试验时间一起记录）：</translation>
    </message>
    <message>
        <source>Quit the console (asks first while a test runs)</source>
        <translation>退出控制台（试验进行中会先询问）</translation>
    </message>
    <message>
        <source>testing the link...</source>
        <translation>正在测试连接...</translation>
    </message>
    <message>
        <source>This ground motion cannot be used: %1</source>
        <translation>此地震动无法使用：%1</translation>
    </message>
    <message>
        <source>ground motion not usable: %1</source>
        <translation>地震动不可用：%1</translation>
    </message>
    <message>
        <source>A test is running</source>
        <translation>试验正在进行</translation>
    </message>
    <message>
        <source>Continue the test</source>
        <translation>继续试验</translation>
    </message>
    <message>
        <source>End the test now? The specimen is held, the test cannot be resumed, and every step so far stays in the record.</source>
        <translation>现在结束试验？试件将保持，试验无法继续，目前为止的每一步都保留在记录中。</translation>
    </message>
    <message>
        <source>End the test and keep the data</source>
        <translation>结束试验并保留数据</translation>
    </message>
    <message>
        <source>link tested: %1 answered; the test is prepared, Start shows the pre-flight check</source>
        <translation>连接已测试：%1 已响应；试验已准备好，“开始”将显示试验前检查</translation>
    </message>
    <message>
        <source>A test is running. Quit the console? The test is ended first: the specimen is held and every step so far stays in the record.</source>
        <translation>试验正在进行。退出控制台？将先结束试验：试件保持，目前为止的每一步都保留在记录中。</translation>
    </message>
    <message>
        <source>End the test, keep the data and quit</source>
        <translation>结束试验、保留数据并退出</translation>
    </message>
    <message>
        <source>(dataSize %1; ctrl sizes %2; daq sizes %3)</source>
        <translation>（dataSize %1；ctrl 尺寸 %2；daq 尺寸 %3）</translation>
    </message>
    <message>
        <source>test finished: %1 steps, t = %2 s</source>
        <translation>试验结束：%1 步，t = %2 s</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>Console &amp;guide</source>
        <translation>控制台指南(&amp;G)</translation>
    </message>
    <message>
        <source>The console&apos;s documentation (docs/console.md)</source>
        <translation>控制台文档（docs/console.md）</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <source>&amp;About HSMU Console</source>
        <translation>关于 HSMU Console(&amp;A)</translation>
    </message>
    <message>
        <source>%1: Start (after the pre-flight check)</source>
        <translation>%1：开始（起飞前检查之后）</translation>
    </message>
    <message>
        <source>%1: Pause</source>
        <translation>%1：暂停</translation>
    </message>
    <message>
        <source>%1: Resume</source>
        <translation>%1：继续</translation>
    </message>
    <message>
        <source>%1: Single step</source>
        <translation>%1：单步</translation>
    </message>
    <message>
        <source>%1: Stop (asks first)</source>
        <translation>%1：停止（先确认）</translation>
    </message>
    <message>
        <source>%1: Emergency hold (every window, always)</source>
        <translation>%1：紧急保持（任何窗口，始终可用）</translation>
    </message>
    <message>
        <source>%1: Add a note to the record</source>
        <translation>%1：向记录添加备注</translation>
    </message>
    <message>
        <source>%1: Open a configuration</source>
        <translation>%1：打开配置</translation>
    </message>
    <message>
        <source>%1: Copy the selected alarms and events</source>
        <translation>%1：复制所选报警和事件</translation>
    </message>
    <message>
        <source>%1: Console guide</source>
        <translation>%1：控制台指南</translation>
    </message>
    <message>
        <source>%1: Quit (asks first while a test runs)</source>
        <translation>%1：退出（试验运行时先确认）</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <source>About HSMU Console</source>
        <translation>关于 HSMU Console</translation>
    </message>
    <message>
        <source>HSMU Console %1
Hybrid simulation with online model updating (Hashemi, Masroor &amp; Mosqueda, EESD 2014).</source>
        <translation>HSMU Console %1
带在线模型更新的混合试验（Hashemi、Masroor 与 Mosqueda，EESD 2014）。</translation>
    </message>
    <message>
        <source>Console guide</source>
        <translation>控制台指南</translation>
    </message>
    <message>
        <source>The guide is docs/console.md of the source tree, installed as share/doc/hsmu/console.md.</source>
        <translation>指南为源码树中的 docs/console.md，安装后为 share/doc/hsmu/console.md。</translation>
    </message>
    <message>
        <source>asking the controller for a fresh specimen...</source>
        <translation>正在向控制器请求新试件...</translation>
    </message>
    <message>
        <source>Real-time hybrid simulation</source>
        <translation>实时混合试验</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ParameterPlot</name>
    <message>
        <source>Time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <source>± %1σ</source>
        <translation>± %1σ</translation>
    </message>
    <message>
        <source>estimate</source>
        <translation>估计值</translation>
    </message>
    <message>
        <source>true value</source>
        <translation>真值</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ParameterTableModel</name>
    <message>
        <source>Double-click to edit; effective on the next step</source>
        <translation>双击编辑；下一步生效</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Sigma</source>
        <translation>σ</translation>
    </message>
    <message>
        <source>Lower</source>
        <translation>下限</translation>
    </message>
    <message>
        <source>Upper</source>
        <translation>上限</translation>
    </message>
    <message>
        <source>Lock</source>
        <translation>锁定</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1：“%2”不是数值</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ParametersPanel</name>
    <message>
        <source>No online model updating in this test.</source>
        <translation>本试验未启用在线模型更新。</translation>
    </message>
    <message>
        <source>Normalized RMS fit error above which the inspector requests an update; effective on the next step</source>
        <translation>归一化 RMS 拟合误差超过此值时检查器请求更新；下一步生效</translation>
    </message>
    <message>
        <source>Fit-error threshold [-]:</source>
        <translation>拟合误差阈值 [-]：</translation>
    </message>
    <message>
        <source>Value, sigma (1 standard deviation) and bounds in the law&apos;s normalized units (u / u_ref, F / F_ref). Double-click a bound to edit it; bound and lock edits take effect on the next step.</source>
        <translation>值、σ（1 倍标准差）及边界均采用滞回模型的归一化单位（u / u_ref，F / F_ref）。双击边界可编辑；边界和锁定的修改在下一步生效。</translation>
    </message>
    <message>
        <source>%1 on %2 at step %3: fit error e = %4 (threshold %5), %6 updates applied</source>
        <translation>%2 上的 %1，第 %3 步：拟合误差 e = %4（阈值 %5），已应用 %6 次更新</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PendingUpdatesPanel</name>
    <message>
        <source>every step</source>
        <translation>每一步</translation>
    </message>
    <message>
        <source>at zero-force crossings of the target</source>
        <translation>在目标力过零时</translation>
    </message>
    <message>
        <source>every N steps</source>
        <translation>每 N 步</translation>
    </message>
    <message>
        <source>on the operator&apos;s approval</source>
        <translation>经操作员批准后</translation>
    </message>
    <message>
        <source>N = </source>
        <translation>N = </translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>当前值</translation>
    </message>
    <message>
        <source>Proposed</source>
        <translation>建议值</translation>
    </message>
    <message>
        <source>Change [%]</source>
        <translation>变化 [%]</translation>
    </message>
    <message>
        <source>Apply updates:</source>
        <translation>应用更新：</translation>
    </message>
    <message>
        <source>No online model updating in this test.</source>
        <translation>本试验未启用在线模型更新。</translation>
    </message>
    <message>
        <source>Updates are applied %1; choose &quot;on the operator&apos;s approval&quot; to decide each one.</source>
        <translation>更新应用方式：%1；选择“经操作员批准后”可逐一决定。</translation>
    </message>
    <message>
        <source>#%1 %2 at t = %3 s (step %4)</source>
        <translation>#%1 %2，t = %3 s（第 %4 步）</translation>
    </message>
    <message>
        <source>Approve</source>
        <translation>批准</translation>
    </message>
    <message>
        <source>Reject</source>
        <translation>拒绝</translation>
    </message>
    <message numerus="yes">
        <source>%n newer proposal(s) were not queued (the queue holds %1); each is in the record.</source>
        <translation>
            <numerusform>%n 个较新的提议未入队（队列容量 %1）；每一个都已记录。</numerusform>
        </translation>
    </message>
    <message>
        <source>, fit error %1</source>
        <translation>，拟合误差 %1</translation>
    </message>
    <message>
        <source>Estimate now</source>
        <translation>当前估计</translation>
    </message>
    <message>
        <source>The target&apos;s current value, the proposed one, the estimator&apos;s value now and the change the proposal makes, in the law&apos;s normalized units</source>
        <translation>目标的当前值、建议值、估计器的当前值以及该建议带来的变化，均为本构律的归一化单位</translation>
    </message>
    <message numerus="yes">
        <source>%n update(s) waiting for a decision.</source>
        <translation>
            <numerusform>%n 个更新等待决定。</numerusform>
        </translation>
    </message>
    <message>
        <source>One proposal per target, renewed every %1 s of test time with the estimator&apos;s latest values (it replaces the one shown); Approve applies the values shown while they are current.</source>
        <translation>每个目标一个建议，每隔 %1 s 试验时间用估计器的最新值更新（替换所显示的建议）；“批准”在其仍有效时应用所显示的值。</translation>
    </message>
    <message>
        <source>: stale (older than %1 s), wait for the next proposal</source>
        <translation>：已过期（超过 %1 s），请等待下一个建议</translation>
    </message>
    <message>
        <source>Approve offsets</source>
        <translation>批准偏移</translation>
    </message>
    <message>
        <source>Reject offsets</source>
        <translation>拒绝偏移</translation>
    </message>
    <message>
        <source>%1%2 (on its bound, no interval)</source>
        <translation>%1%2（位于边界，无区间）</translation>
    </message>
    <message>
        <source>%1 +- %2%3 (95 %)</source>
        <translation>%1 +- %2%3（95 %）</translation>
    </message>
    <message>
        <source>Offsets #%1 for the twins: u0 = %2, F0 = %3</source>
        <translation>孪生模型的偏移 #%1：u0 = %2，F0 = %3</translation>
    </message>
    <message>
        <source>Found at t = %1 s (step %2) on %3 samples; the specimen&apos;s NRMSE %4 without them, %5 with them. They reach the twins (F = F_law(u - u0) + F0) only if you approve them, whatever the policy.</source>
        <translation>于 t = %1 s（第 %2 步）基于 %3 个样本得到；试件的 NRMSE 不含偏移为 %4，含偏移为 %5。无论采用何种策略，只有经您批准后才会应用到孪生模型（F = F_law(u - u0) + F0）。</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PlotElementPicker</name>
    <message>
        <source>Element:</source>
        <translation>单元：</translation>
    </message>
    <message>
        <source>The element this plot shows</source>
        <translation>此图显示的单元</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PlotTools</name>
    <message>
        <source>x = %1, y = %2</source>
        <translation>x = %1，y = %2</translation>
    </message>
    <message>
        <source>%1: %2 at %3</source>
        <translation>%1：%2（位于 %3）</translation>
    </message>
    <message>
        <source>%1: cannot be written (%2)</source>
        <translation>%1：无法写入（%2）</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>自动缩放</translation>
    </message>
    <message>
        <source>Channels</source>
        <translation>通道</translation>
    </message>
    <message>
        <source>curve %1</source>
        <translation>曲线 %1</translation>
    </message>
    <message>
        <source>Export visible data as CSV...</source>
        <translation>将可见数据导出为 CSV...</translation>
    </message>
    <message>
        <source>Export visible data</source>
        <translation>导出可见数据</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::PreflightDialog</name>
    <message>
        <source>Pre-flight check</source>
        <translation>预检</translation>
    </message>
    <message>
        <source>Integration and stability</source>
        <translation>积分与稳定性</translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation>积分器：</translation>
    </message>
    <message>
        <source>Time step dt [s]:</source>
        <translation>时间步长 dt [s]：</translation>
    </message>
    <message>
        <source>Steps:</source>
        <translation>步数：</translation>
    </message>
    <message>
        <source>Ground motion:</source>
        <translation>地震动：</translation>
    </message>
    <message>
        <source>%1, PGA %2 m/s²</source>
        <translation>%1，PGA %2 m/s²</translation>
    </message>
    <message>
        <source>omega_max [rad/s]:</source>
        <translation>omega_max [rad/s]：</translation>
    </message>
    <message>
        <source>omega_max dt [-] / limit:</source>
        <translation>omega_max dt [-] / 极限：</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>unconditionally stable</source>
        <translation>无条件稳定</translation>
    </message>
    <message>
        <source>Stable: %1</source>
        <translation>稳定：%1</translation>
    </message>
    <message>
        <source>UNSTABLE: %1%2</source>
        <translation>不稳定：%1%2</translation>
    </message>
    <message>
        <source> (forced by the configuration)</source>
        <translation> （由配置强制）</translation>
    </message>
    <message>
        <source>Check:</source>
        <translation>检查结果：</translation>
    </message>
    <message>
        <source>Specimens: limits and initial measured values</source>
        <translation>试件：限值与初始实测值</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>单元</translation>
    </message>
    <message>
        <source>Max |d|</source>
        <translation>最大 |d|</translation>
    </message>
    <message>
        <source>Max |F|</source>
        <translation>最大 |F|</translation>
    </message>
    <message>
        <source>Max |Δd| per step</source>
        <translation>每步最大 |Δd|</translation>
    </message>
    <message>
        <source>Measured d</source>
        <translation>实测 d</translation>
    </message>
    <message>
        <source>Measured F</source>
        <translation>实测 F</translation>
    </message>
    <message>
        <source>Measured d and F: what the specimen reported after the link was prepared, before any target was sent.</source>
        <translation>实测 d 和 F：链路准备就绪后、发送任何目标值之前试件报告的数值。</translation>
    </message>
    <message>
        <source>I confirm the zero offsets: with the specimen unloaded the actuator displacement and the load cell read zero.</source>
        <translation>我确认零点偏移：试件卸载时，作动器位移和力传感器读数均为零。</translation>
    </message>
    <message>
        <source>Start test</source>
        <translation>开始试验</translation>
    </message>
    <message>
        <source>Please check:</source>
        <translation>请检查：</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>explicit Newmark</source>
        <translation>显式 Newmark</translation>
    </message>
    <message>
        <source>alpha-OS</source>
        <translation>alpha-OS</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>未测量</translation>
    </message>
    <message>
        <source>Measured d and F: what the specimen reported after the link was prepared, before any target was sent; for a specimen loaded by an earlier test, d is its last committed deformation and F is measured at the first step.</source>
        <translation>实测 d 和 F：链路准备好后、发送任何目标之前试件报告的值；对于已被先前试验加载的试件，d 是其最后一个已提交步的变形，F 在第一步测量。</translation>
    </message>
    <message>
        <source>Specimen loaded by an earlier test</source>
        <translation>试件已被先前的试验加载</translation>
    </message>
    <message>
        <source>%1 has %L2 committed steps from an earlier test; its last committed deformation is %3 %4. This test starts from rest: its first target moves the specimen from there.</source>
        <translation>%1 已有先前试验的 %L2 个已提交步；其最后一个已提交步的变形为 %3 %4。本试验从静止开始：第一个目标将使试件从该位置移动。</translation>
    </message>
    <message>
        <source>Its controller refused a fresh specimen (%1): replace the specimen at the controller and restart the controller without its state file, or continue on the loaded specimen.</source>
        <translation>其控制器拒绝了新试件（%1）：请在控制器处更换试件，并在不带状态文件的情况下重启控制器，或在已加载的试件上继续。</translation>
    </message>
    <message>
        <source>Choose: continue on the loaded specimen (its damage is part of this test), or a fresh specimen (its controller resets it to step 0, then this check is shown again).</source>
        <translation>请选择：在已加载的试件上继续（其损伤计入本试验），或使用新试件（其控制器将其重置到第 0 步，然后再次显示本检查）。</translation>
    </message>
    <message>
        <source>Continue on the loaded specimen</source>
        <translation>在已加载的试件上继续</translation>
    </message>
    <message>
        <source>Fresh specimen</source>
        <translation>新试件</translation>
    </message>
    <message>
        <source>Reset the specimen</source>
        <translation>重置试件</translation>
    </message>
    <message>
        <source>Continuing would move it by about %1 %2 at the first step, more than the increment limit %3 %2: the controller would hold the test. Choose a fresh specimen, or bring the specimen back to rest at the controller.</source>
        <translation>继续将使其在第一步移动约 %1 %2，超过增量限值 %3 %2：控制器会保持（暂停）试验。请选择新试件，或在控制器处使试件回到静止位置。</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReidentifyDialog</name>
    <message>
        <source>Re-identify</source>
        <translation>重新识别</translation>
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
        <translation>无：使用记录的设置</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>浏览...</translation>
    </message>
    <message>
        <source>Override settings</source>
        <translation>覆盖设置</translation>
    </message>
    <message>
        <source>JSON (*.json);;All files (*)</source>
        <translation>JSON (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <source>Override (JSON)</source>
        <translation>覆盖 (JSON)</translation>
    </message>
    <message>
        <source>{&quot;model&quot;: ..., &quot;updating&quot;: ...} merged into the recorded settings, as hsmu replay --config</source>
        <translation>{&quot;model&quot;: ..., &quot;updating&quot;: ...} 合并到记录的设置中，同 hsmu replay --config</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>确定</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReplayEventList</name>
    <message>
        <source>Time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>步</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Event, alarm or note</source>
        <translation>事件、报警或备注</translation>
    </message>
    <message>
        <source>operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <source>note</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>Double-click (or Enter) to jump to the step</source>
        <translation>双击（或回车）跳转到该步</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1，%2</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReplayReadout</name>
    <message>
        <source>Quantity</source>
        <translation>物理量</translation>
    </message>
    <message>
        <source>Value at the cursor</source>
        <translation>光标处的值</translation>
    </message>
    <message>
        <source>step</source>
        <translation>步</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>时间 t [s]</translation>
    </message>
    <message>
        <source>ag [m/s²]</source>
        <translation>地面加速度 ag [m/s²]</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::ReplayWindow</name>
    <message>
        <source>Open record</source>
        <translation>打开记录</translation>
    </message>
    <message>
        <source>HSMU records (*.h5 *.hdf5);;All files (*)</source>
        <translation>HSMU 记录 (*.h5 *.hdf5);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Cannot open the record</source>
        <translation>无法打开记录</translation>
    </message>
    <message>
        <source>HSMU Replay - %1 (%2)</source>
        <translation>HSMU 回放 - %1（%2）</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>回放</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <source> Speed </source>
        <translation> 速度 </translation>
    </message>
    <message>
        <source>%1 x</source>
        <translation>%1 倍</translation>
    </message>
    <message>
        <source>Test seconds per wall second</source>
        <translation>每秒实际时间对应的试验秒数</translation>
    </message>
    <message>
        <source>Scrub through the record</source>
        <translation>拖动浏览记录</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source> t = %1 s   step %2 of %3 </source>
        <translation> t = %1 s   第 %2 / %3 步 </translation>
    </message>
    <message>
        <source>Re-identify...</source>
        <translation>重新识别...</translation>
    </message>
    <message>
        <source>Identify the specimen again with other settings and overlay the parameter history</source>
        <translation>用其他设置重新识别试件，并叠加参数历程</translation>
    </message>
    <message>
        <source>identifying</source>
        <translation>识别中</translation>
    </message>
    <message>
        <source>Re-identifying the specimen</source>
        <translation>正在重新识别试件</translation>
    </message>
    <message>
        <source>re-identified (%1)</source>
        <translation>重新识别 (%1)</translation>
    </message>
    <message>
        <source>Re-identification failed</source>
        <translation>重新识别失败</translation>
    </message>
    <message>
        <source>Events, alarms and notes</source>
        <translation>事件、报警和备注</translation>
    </message>
    <message>
        <source>Values at the cursor</source>
        <translation>光标处的值</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>Export time window as &amp;CSV...</source>
        <translation>将时间窗导出为 &amp;CSV...</translation>
    </message>
    <message>
        <source>Export time window</source>
        <translation>导出时间窗</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Export &amp;plots (PNG, SVG or PDF)...</source>
        <translation>导出图表(&amp;P)（PNG、SVG 或 PDF）...</translation>
    </message>
    <message>
        <source>Export plots</source>
        <translation>导出图表</translation>
    </message>
    <message>
        <source>PNG images (*.png);;SVG drawings (*.svg);;PDF documents (*.pdf)</source>
        <translation>PNG 图像 (*.png);;SVG 图形 (*.svg);;PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>关闭(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Playback</source>
        <translation>回放(&amp;P)</translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation>后退一步(&amp;B)</translation>
    </message>
    <message>
        <source>Step &amp;forward</source>
        <translation>前进一步(&amp;F)</translation>
    </message>
    <message>
        <source>To the &amp;start</source>
        <translation>到开头(&amp;S)</translation>
    </message>
    <message>
        <source>To the &amp;end</source>
        <translation>到结尾(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::RthsPanel</name>
    <message>
        <source>RTHS proposal #%1 rejected</source>
        <translation>RTHS 提议 #%1 已拒绝</translation>
    </message>
    <message>
        <source>RTHS proposal #%1 approved</source>
        <translation>RTHS 提议 #%1 已批准</translation>
    </message>
    <message>
        <source>Damper twin</source>
        <translation>阻尼器孪生模型</translation>
    </message>
    <message>
        <source>Tracking</source>
        <translation>跟踪</translation>
    </message>
    <message>
        <source>Go on with the held run from the tick where it held (refused while a limit is still breached)</source>
        <translation>从保持处的周期继续已保持的试验（限值仍被超出时拒绝）</translation>
    </message>
    <message>
        <source>Not resumed: %1</source>
        <translation>未继续：%1</translation>
    </message>
    <message>
        <source>RTHS run not resumed: %1</source>
        <translation>RTHS 试验未继续：%1</translation>
    </message>
    <message>
        <source>RTHS resume</source>
        <translation>RTHS 继续</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>Resumed</source>
        <translation>已继续</translation>
    </message>
    <message>
        <source>No RTHS run yet.</source>
        <translation>尚无 RTHS 试验。</translation>
    </message>
    <message>
        <source>Run:</source>
        <translation>试验：</translation>
    </message>
    <message>
        <source>Benchmark case %1</source>
        <translation>基准算例 %1</translation>
    </message>
    <message>
        <source>Configuration file</source>
        <translation>配置文件</translation>
    </message>
    <message>
        <source>RTHS configuration (.json)</source>
        <translation>RTHS 配置（.json）</translation>
    </message>
    <message>
        <source>Choose an RTHS configuration file</source>
        <translation>选择 RTHS 配置文件</translation>
    </message>
    <message>
        <source>Pace:</source>
        <translation>节奏：</translation>
    </message>
    <message>
        <source>Fast (simulated)</source>
        <translation>快速（模拟）</translation>
    </message>
    <message>
        <source>Real time</source>
        <translation>实时</translation>
    </message>
    <message>
        <source>Duration:</source>
        <translation>时长：</translation>
    </message>
    <message>
        <source>whole record</source>
        <translation>整条记录</translation>
    </message>
    <message>
        <source>Stop the run after this many seconds of test time (0: the whole record)</source>
        <translation>试验时间达到该秒数后停止（0：整条记录）</translation>
    </message>
    <message>
        <source>Start RTHS</source>
        <translation>开始 RTHS</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>保持</translation>
    </message>
    <message>
        <source>Hold the loop before its next tick (Resume goes on from there)</source>
        <translation>在下一个周期前保持回路（“继续”从该处继续）</translation>
    </message>
    <message>
        <source>Emergency hold</source>
        <translation>紧急保持</translation>
    </message>
    <message>
        <source>Live tracking</source>
        <translation>实时跟踪</translation>
    </message>
    <message>
        <source>Warning above</source>
        <translation>警告阈值</translation>
    </message>
    <message>
        <source>Critical above</source>
        <translation>严重阈值</translation>
    </message>
    <message>
        <source>J1 delay</source>
        <translation>J1 延迟</translation>
    </message>
    <message>
        <source>J2 tracking error</source>
        <translation>J2 跟踪误差</translation>
    </message>
    <message>
        <source>RTHS configuration</source>
        <translation>RTHS 配置</translation>
    </message>
    <message>
        <source>Configuration (*.json)</source>
        <translation>配置（*.json）</translation>
    </message>
    <message>
        <source>choose an RTHS configuration file</source>
        <translation>请选择 RTHS 配置文件</translation>
    </message>
    <message>
        <source>Cannot start the RTHS run: %1</source>
        <translation>无法开始 RTHS 试验：%1</translation>
    </message>
    <message>
        <source>RTHS run &apos;%1&apos; started</source>
        <translation>RTHS 试验 &apos;%1&apos; 已开始</translation>
    </message>
    <message>
        <source>RTHS hold</source>
        <translation>RTHS 保持</translation>
    </message>
    <message>
        <source>RTHS emergency hold</source>
        <translation>RTHS 紧急保持</translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation>未应用：%1</translation>
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
        <translation>幅值误差：%1 %</translation>
    </message>
    <message>
        <source>Amplitude error: -- %</source>
        <translation>幅值误差：-- %</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>Finished: %1 ticks (%2 s); whole run J1 %3 ms, J2 %4 %</source>
        <translation>已完成：%1 个周期（%2 s）；全程 J1 %3 ms，J2 %4 %</translation>
    </message>
    <message>
        <source>RTHS run finished: %1 ticks</source>
        <translation>RTHS 试验已完成：%1 个周期</translation>
    </message>
    <message>
        <source>Held after %1 ticks: %2</source>
        <translation>%1 个周期后保持：%2</translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation>控制器：</translation>
    </message>
    <message>
        <source>built-in virtual lab, or tcp://HOST:PORT of hsmu-controller --rths</source>
        <translation>内置虚拟实验室，或 hsmu-controller --rths 的 tcp://主机:端口</translation>
    </message>
    <message>
        <source>Empty: the loop runs in the console. tcp://HOST:PORT: monitor the loop hsmu-controller --rths runs (its token from HSMU_CONTROLLER_TOKEN)</source>
        <translation>留空：回路在控制台中运行。tcp://主机:端口：监视 hsmu-controller --rths 运行的回路（令牌取自 HSMU_CONTROLLER_TOKEN）</translation>
    </message>
    <message>
        <source>controller: an RTHS loop is monitored over tcp://HOST:PORT (hsmu-controller --rths)</source>
        <translation>控制器：RTHS 回路通过 tcp://主机:端口 监视（hsmu-controller --rths）</translation>
    </message>
    <message>
        <source>real time; pre-flight: %1</source>
        <translation>实时；预检：%1</translation>
    </message>
    <message>
        <source>fast; pre-flight: %1</source>
        <translation>快速；预检：%1</translation>
    </message>
    <message>
        <source>on the controller %1:%2</source>
        <translation>在控制器 %1:%2 上</translation>
    </message>
    <message>
        <source>Running &apos;%1&apos; at %2 Hz (%3)</source>
        <translation>正在运行 &apos;%1&apos;，%2 Hz（%3）</translation>
    </message>
    <message>
        <source>The RTHS run could not be followed: %1</source>
        <translation>无法跟踪该 RTHS 试验：%1</translation>
    </message>
    <message>
        <source>Record folder:</source>
        <translation>记录文件夹：</translation>
    </message>
    <message>
        <source>not recorded</source>
        <translation>不记录</translation>
    </message>
    <message>
        <source>Every tick of a run from this view goes to record.h5 in this folder (record-2.h5, record-3.h5, ... when taken: nothing is overwritten); empty: not recorded</source>
        <translation>从此视图启动的试验的每个节拍写入此文件夹中的 record.h5（已存在时写入 record-2.h5、record-3.h5……：不覆盖任何文件）；留空：不记录</translation>
    </message>
    <message>
        <source>Recorded on the controller, not by the console: %1</source>
        <translation>由控制器记录，而非控制台：%1</translation>
    </message>
    <message>
        <source>Not recorded (no record folder)</source>
        <translation>不记录（未指定记录文件夹）</translation>
    </message>
    <message>
        <source>Recording every tick to %1</source>
        <translation>正在将每个节拍记录到 %1</translation>
    </message>
    <message>
        <source>Recorded on the controller, not by the console (waiting for the controller&apos;s description)</source>
        <translation>由控制器记录，而非控制台（正在等待控制器的描述）</translation>
    </message>
    <message>
        <source>The record %1 is incomplete: %2</source>
        <translation>记录 %1 不完整：%2</translation>
    </message>
    <message>
        <source>Recorded %1 ticks to %2</source>
        <translation>已将 %1 个节拍记录到 %2</translation>
    </message>
    <message>
        <source>No estimate: the command&apos;s RMS %1 mm is below %2 mm</source>
        <translation>无估计：指令的均方根 %1 mm 低于 %2 mm</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::RthsSession</name>
    <message>
        <source>no controller&apos;s RTHS run is going</source>
        <translation>没有正在进行的控制器 RTHS 试验</translation>
    </message>
    <message>
        <source>this RTHS run has no damper twin</source>
        <translation>此 RTHS 试验没有阻尼器孪生模型</translation>
    </message>
    <message>
        <source>the link to the controller is closed</source>
        <translation>与控制器的连接已关闭</translation>
    </message>
    <message>
        <source>no RTHS run is going</source>
        <translation>没有正在进行的 RTHS 试验</translation>
    </message>
    <message>
        <source>no held RTHS run to resume</source>
        <translation>没有可继续的已保持 RTHS 试验</translation>
    </message>
    <message>
        <source>an RTHS run is already going</source>
        <translation>已有 RTHS 试验在运行</translation>
    </message>
    <message>
        <source>refused in pre-flight: %1</source>
        <translation>预检拒绝：%1</translation>
    </message>
    <message>
        <source>the controller&apos;s (%1:%2)</source>
        <translation>由控制器执行（%1:%2）</translation>
    </message>
    <message>
        <source>the link to the controller was lost: %1 (the controller holds the loop per its --monitor-loss policy)</source>
        <translation>与控制器的链路已断开：%1（控制器按其 --monitor-loss 策略保持回路）</translation>
    </message>
    <message>
        <source>the record cannot be created in %1: %2</source>
        <translation>无法在 %1 中创建记录：%2</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SettingsDialog</name>
    <message>
        <source>Settings</source>
        <translation>设置</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>系统默认</translation>
    </message>
    <message>
        <source>Clear recent files</source>
        <translation>清除最近文件</translation>
    </message>
    <message>
        <source>empty: tests are not recorded</source>
        <translation>留空：不记录试验</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>浏览...</translation>
    </message>
    <message>
        <source>Record folder</source>
        <translation>记录文件夹</translation>
    </message>
    <message>
        <source>Record folder (HDF5):</source>
        <translation>记录文件夹（HDF5）：</translation>
    </message>
    <message>
        <source>Language:</source>
        <translation>语言：</translation>
    </message>
    <message>
        <source>Recent files:</source>
        <translation>最近文件：</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>确定</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>A new language applies at once, to every window.</source>
        <translation>新语言立即应用于所有窗口。</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SetupPanel</name>
    <message>
        <source>Record&apos;s sample step [s]:</source>
        <translation>记录采样步长 [s]：</translation>
    </message>
    <message>
        <source>The time between the record&apos;s samples. A file of acceleration values only (one column) needs it; an AT2 header or a time column gives its own. Not the integration step dt.</source>
        <translation>记录相邻采样之间的时间。仅含加速度数值（一列）的文件需要它；AT2 文件头或时间列自带步长。它不是积分步长 dt。</translation>
    </message>
    <message>
        <source>from the file</source>
        <translation>取自文件</translation>
    </message>
    <message>
        <source>No configuration loaded: choose a preset or open a file.</source>
        <translation>未加载配置：请选择预设或打开文件。</translation>
    </message>
    <message>
        <source>Safety limits (0 = none; the specimen&apos;s units)</source>
        <translation>安全限值（0 = 无；采用试件的单位）</translation>
    </message>
    <message>
        <source>Specimen</source>
        <translation>试件</translation>
    </message>
    <message>
        <source>Max |d|</source>
        <translation>最大 |d|</translation>
    </message>
    <message>
        <source>Max |F|</source>
        <translation>最大 |F|</translation>
    </message>
    <message>
        <source>Max |Δd| per step</source>
        <translation>每步最大 |Δd|</translation>
    </message>
    <message>
        <source>Apply (reload the test)</source>
        <translation>应用（重新加载试验）</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>the configuration&apos;s record</source>
        <translation>配置中的记录</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>浏览...</translation>
    </message>
    <message>
        <source>Ground motion file:</source>
        <translation>地震动文件：</translation>
    </message>
    <message>
        <source>Scale [-]:</source>
        <translation>缩放系数 [-]：</translation>
    </message>
    <message>
        <source>Time step dt [s]:</source>
        <translation>时间步长 dt [s]：</translation>
    </message>
    <message>
        <source>whole record</source>
        <translation>完整记录</translation>
    </message>
    <message>
        <source>Duration [s]:</source>
        <translation>时长 [s]：</translation>
    </message>
    <message>
        <source>explicit Newmark</source>
        <translation>显式 Newmark</translation>
    </message>
    <message>
        <source>alpha-OS</source>
        <translation>alpha-OS</translation>
    </message>
    <message>
        <source>Integrator:</source>
        <translation>积分器：</translation>
    </message>
    <message>
        <source>alpha-OS alpha [-]:</source>
        <translation>alpha-OS 的 alpha [-]：</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>built-in virtual lab</source>
        <translation>内置虚拟实验室</translation>
    </message>
    <message>
        <source>hsmu-controller over TCP</source>
        <translation>通过 TCP 连接 hsmu-controller</translation>
    </message>
    <message>
        <source>Specimens driven by:</source>
        <translation>试件驱动方式：</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>主机：</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>端口：</translation>
    </message>
    <message>
        <source>Online model updating</source>
        <translation>在线模型更新</translation>
    </message>
    <message>
        <source>enabled</source>
        <translation>启用</translation>
    </message>
    <message>
        <source>Fit-error threshold [-]:</source>
        <translation>拟合误差阈值 [-]：</translation>
    </message>
    <message>
        <source>Ground motion record</source>
        <translation>地震动记录</translation>
    </message>
    <message>
        <source>Ground motions (*.AT2 *.at2 *.txt *.csv *.dat);;All files (*)</source>
        <translation>地震动 (*.AT2 *.at2 *.txt *.csv *.dat);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Configuration: %1
%2</source>
        <translation>配置：%1
%2</translation>
    </message>
    <message>
        <source>(built in)</source>
        <translation>（内置）</translation>
    </message>
    <message>
        <source>built-in %1 record</source>
        <translation>内置 %1 记录</translation>
    </message>
    <message>
        <source>d in %1, F in %2</source>
        <translation>d 单位 %1，F 单位 %2</translation>
    </message>
    <message>
        <source>no configuration loaded</source>
        <translation>未加载配置</translation>
    </message>
    <message>
        <source>safety limit of %1: &apos;%2&apos; is not a number &gt;= 0</source>
        <translation>%1 的安全限值：“%2”不是 &gt;= 0 的数值</translation>
    </message>
    <message>
        <source>this configuration has no updating section to enable</source>
        <translation>该配置没有可启用的 updating 部分</translation>
    </message>
    <message>
        <source>OpenFresco SimApp site</source>
        <translation>OpenFresco SimApp 站点</translation>
    </message>
    <message>
        <source>OpenFresco GenericTCP controller</source>
        <translation>OpenFresco GenericTCP 控制器</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>The token hsmu-controller --token expects; not saved</source>
        <translation>hsmu-controller --token 所需的令牌；不保存</translation>
    </message>
    <message>
        <source>Token:</source>
        <translation>令牌：</translation>
    </message>
    <message>
        <source>Test link</source>
        <translation>测试连接</translation>
    </message>
    <message>
        <source>Connect to the controller now (the test is prepared; nothing moves before the pre-flight check)</source>
        <translation>立即连接控制器（试验会被准备；在试验前检查之前不会有任何运动）</translation>
    </message>
    <message>
        <source>When updates are applied is chosen in the Pending updates panel (one setting for the test).</source>
        <translation>何时应用更新在“待处理更新”面板中选择（试验只有一个设置）。</translation>
    </message>
    <message>
        <source>OpenSees adapter element (numerical substructure)</source>
        <translation>OpenSees adapter 单元（数值子结构）</translation>
    </message>
    <message>
        <source>hsmu-controller over TLS (the configuration&apos;s tls block)</source>
        <translation>通过 TLS 连接 hsmu-controller（配置中的 tls 块）</translation>
    </message>
    <message>
        <source>OpenSees listens: start the model with its `element adapter ... PORT` first (its analyze must have at least the test&apos;s steps). A step is final once the next one is sent: after a hold the test cannot repeat it.</source>
        <translation>OpenSees 监听：请先用其 `element adapter ... PORT` 启动模型（其 analyze 的步数至少为试验步数）。发送下一步后该步即为最终：暂停后试验无法重复该步。</translation>
    </message>
    <message>
        <source>synthetic</source>
        <translation>合成</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SetupSketchView</name>
    <message>
        <source>%1: no 2-D drawing of its setup %2 (a 3-D or aggregated setup); its actuators are in the plot.</source>
        <translation>%1：其装置 %2 无二维图（三维或组合装置）；其作动器见曲线图。</translation>
    </message>
    <message>
        <source>deformed shape x%1 (solid), at rest (dashed)</source>
        <translation>变形形状 x%1（实线），静止（虚线）</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SiteHealthLabel</name>
    <message>
        <source>down</source>
        <translation>断开</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>last fault: %1</source>
        <translation>最近故障：%1</translation>
    </message>
    <message>
        <source> (faults: %1)</source>
        <translation> (故障：%1)</translation>
    </message>
    <message>
        <source>connected, %1 ms</source>
        <translation>已连接，%1 ms</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>已连接</translation>
    </message>
    <message>
        <source>link: %1</source>
        <translation>链路：%1</translation>
    </message>
    <message>
        <source>no link</source>
        <translation>无链路</translation>
    </message>
    <message>
        <source>(connects at start)</source>
        <translation>（开始时连接）</translation>
    </message>
    <message>
        <source>built-in virtual lab</source>
        <translation>内置虚拟实验室</translation>
    </message>
    <message>
        <source>%1: built-in virtual lab</source>
        <translation>%1：内置虚拟实验室</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SiteHealthView</name>
    <message>
        <source>Sites</source>
        <translation>站点</translation>
    </message>
    <message>
        <source>Site</source>
        <translation>站点</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>地址</translation>
    </message>
    <message>
        <source>Specimens</source>
        <translation>试件</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>the controller above</source>
        <translation>上方的控制器</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::SynchronizationPlot</name>
    <message>
        <source>Synchronization: measured against desired</source>
        <translation>同步图：实测对期望</translation>
    </message>
    <message>
        <source>desired displacement y [mm]</source>
        <translation>期望位移 y [mm]</translation>
    </message>
    <message>
        <source>measured displacement xm [mm]</source>
        <translation>实测位移 xm [mm]</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>实测</translation>
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
        <translation>第 %1 / %2 步</translation>
    </message>
    <message>
        <source>%1 steps/s</source>
        <translation>%1 步/s</translation>
    </message>
    <message>
        <source>not recording</source>
        <translation>未记录</translation>
    </message>
    <message>
        <source>recording: %1/%2</source>
        <translation>记录中：%1/%2</translation>
    </message>
    <message>
        <source>%1, %2 left</source>
        <translation>%1，剩余 %2</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TestWorker</name>
    <message>
        <source>link restored: the test resumed after an automatic reconnect</source>
        <translation>链路已恢复：试验在自动重连后继续</translation>
    </message>
    <message>
        <source>emergency hold by the operator</source>
        <translation>操作员触发紧急保持</translation>
    </message>
    <message>
        <source>the record cannot be written: %1</source>
        <translation>无法写入记录：%1</translation>
    </message>
    <message>
        <source>this test has no model updating</source>
        <translation>本试验未启用模型更新</translation>
    </message>
    <message>
        <source>%1: the lower bound must be a number not above the upper bound</source>
        <translation>%1：下限必须是不大于上限的数值</translation>
    </message>
    <message>
        <source>%1: bounds [%2, %3] refused (they would not keep the law admissible)</source>
        <translation>%1：边界 [%2, %3] 被拒绝（会使滞回模型不再容许）</translation>
    </message>
    <message>
        <source>%1: the %2 cannot lock this parameter</source>
        <translation>%1：%2 无法锁定此参数</translation>
    </message>
    <message>
        <source>update #%1 was not applied (no longer pending, or refused by the law; see the alarms)</source>
        <translation>更新 #%1 未应用（已不再待处理，或被滞回模型拒绝；请查看报警）</translation>
    </message>
    <message>
        <source>update #%1 is no longer pending</source>
        <translation>更新 #%1 已不再待处理</translation>
    </message>
    <message>
        <source>offsets #%1 are no longer pending</source>
        <translation>偏移 #%1 已不再待定</translation>
    </message>
    <message>
        <source>offsets #%1 were not applied: %2</source>
        <translation>偏移 #%1 未应用：%2</translation>
    </message>
    <message>
        <source>the fit-error threshold must be a positive number</source>
        <translation>拟合误差阈值必须为正数</translation>
    </message>
    <message>
        <source>the note was not kept: this test is not recorded</source>
        <translation>备注未保存：此试验没有记录</translation>
    </message>
    <message>
        <source>link fault (%1): reconnecting in %2 s (attempt %3 of %4)</source>
        <translation>链路故障（%1）：%2 s 后重新连接（第 %3 次，共 %4 次）</translation>
    </message>
    <message>
        <source>the note was not kept: %1</source>
        <translation>备注未保存：%1</translation>
    </message>
    <message>
        <source>update #%1 was not applied: the estimate has moved on and #%2 replaced it; check #%2 and approve it if it is right</source>
        <translation>更新 #%1 未应用：估计已变化，#%2 已替换它；请检查 #%2，若正确则批准</translation>
    </message>
    <message>
        <source>update #%1 was not applied: it is older than one proposal interval (%2 s) and no longer what the estimator believes; wait for the next proposal</source>
        <translation>更新 #%1 未应用：它早于一个建议间隔（%2 s），已不是估计器的当前结果；请等待下一个建议</translation>
    </message>
    <message>
        <source>update #%1 is no longer pending: #%2 replaced it</source>
        <translation>更新 #%1 已不再待定：#%2 已替换它</translation>
    </message>
    <message>
        <source>the controller of %1 refused a fresh specimen: %2; replace the specimen at the controller, or continue on the loaded specimen</source>
        <translation>%1 的控制器拒绝了新试件：%2；请在控制器处更换试件，或在已加载的试件上继续</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::TrackingHistoryPlot</name>
    <message>
        <source>Delay and amplitude error (moving window)</source>
        <translation>延迟与幅值误差（滑动窗口）</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <source>delay [ms]</source>
        <translation>延迟 [ms]</translation>
    </message>
    <message>
        <source>amplitude error [%]</source>
        <translation>幅值误差 [%]</translation>
    </message>
</context>
<context>
    <name>hsmu::gui::RthsTwinPanel</name>
    <message>
        <source>Proposal #%1 refused: %2</source>
        <translation>提议 #%1 被拒绝：%2</translation>
    </message>
    <message>
        <source>Proposal #%1 applied before tick %2</source>
        <translation>提议 #%1 已在节拍 %2 之前应用</translation>
    </message>
    <message>
        <source>Proposal #%1 rejected before tick %2: nothing applied</source>
        <translation>提议 #%1 在节拍 %2 之前被拒绝：未应用任何内容</translation>
    </message>
    <message>
        <source>Proposal #%1 %2</source>
        <translation>提议 #%1：%2</translation>
    </message>
    <message>
        <source>Proposal #%1 before tick %2: waiting for your approval</source>
        <translation>节拍 %2 之前的提议 #%1：等待您的批准</translation>
    </message>
    <message>
        <source>Reject</source>
        <translation>拒绝</translation>
    </message>
    <message>
        <source>Apply the selected proposal before the loop&apos;s next tick (refused if outside the bounds)</source>
        <translation>在回路的下一个节拍之前应用所选提议（超出界限则被拒绝）</translation>
    </message>
    <message>
        <source>Approve</source>
        <translation>批准</translation>
    </message>
    <message>
        <source>Proposals waiting for approval (the controller&apos;s identification)</source>
        <translation>等待批准的提议（控制器的识别）</translation>
    </message>
    <message>
        <source>Proposed values</source>
        <translation>提议值</translation>
    </message>
    <message>
        <source>Fit error</source>
        <translation>拟合误差</translation>
    </message>
    <message>
        <source>Tick (time)</source>
        <translation>节拍（时间）</translation>
    </message>
    <message>
        <source>Proposal</source>
        <translation>提议</translation>
    </message>
    <message>
        <source>Applied before tick %1 (t = %2 s; %3): %4</source>
        <translation>已在节拍 %1 之前应用（t = %2 s；%3）：%4</translation>
    </message>
    <message>
        <source>Refused: %1</source>
        <translation>被拒绝：%1</translation>
    </message>
    <message>
        <source>Refused before tick %1: %2</source>
        <translation>在节拍 %1 之前被拒绝：%2</translation>
    </message>
    <message>
        <source>Sent: applied before the loop&apos;s next tick, or refused with the reason</source>
        <translation>已发送：在回路的下一个节拍之前应用，或附原因被拒绝</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>未发送：%1</translation>
    </message>
    <message>
        <source>type at least one new value</source>
        <translation>请至少输入一个新值</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1：“%2”不是数字</translation>
    </message>
    <message>
        <source>Damper twin: none in this run</source>
        <translation>阻尼器孪生模型：本试验中没有</translation>
    </message>
    <message>
        <source>Damper twin (storey of DOF %1), values in its scales uRef, fRef</source>
        <translation>阻尼器孪生模型（自由度 %1 所在楼层），数值按其尺度 uRef、fRef</translation>
    </message>
    <message>
        <source>Apply the new values to the twin before the loop&apos;s next tick (checked against the bounds first)</source>
        <translation>在回路的下一个节拍之前将新值应用于孪生模型（先按界限检查）</translation>
    </message>
    <message>
        <source>Send update</source>
        <translation>发送更新</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>新值</translation>
    </message>
    <message>
        <source>Bounds</source>
        <translation>界限</translation>
    </message>
    <message>
        <source>Physical value</source>
        <translation>物理值</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
</context>
</TS>
