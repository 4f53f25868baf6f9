<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>fog::ui::BenchPreset</name>
    <message>
        <location filename="../../ui/bench_presets.cpp" line="+12"/>
        <source>Paper: 0.1 Hz / 10° 294 s + 1 Hz / 3° 60 s</source>
        <translation>论文：0.1 Hz / 10° 294 s + 1 Hz / 3° 60 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Paper slow: 0.1 Hz / 10°, 294 s</source>
        <translation>论文慢速：0.1 Hz / 10°，294 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Paper fast: 1 Hz / 3°, 60 s</source>
        <translation>论文快速：1 Hz / 3°，60 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quick: 1 Hz / 3°, 20 s</source>
        <translation>快速：1 Hz / 3°，20 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro noise: 10 min at rest on X, then 1 Hz / 3°, 60 s</source>
        <translation>陀螺噪声：X 轴静止 10 分钟，然后 1 Hz / 3°，60 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency response: X, 20 frequencies 0.05 – 11 Hz, 11 min</source>
        <translation>频率响应：X 轴，0.05 – 11 Hz 共 20 个频率，11 分钟</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Frequency response, standard: X, 21 one-third octaves 0.1 – 10 Hz, 7.6 min</source>
        <translation>频率响应（标准）：X 轴，0.1 – 10 Hz 共 21 个三分之一倍频程，7.6 分钟</translation>
    </message>
</context>
<context>
    <name>fog::ui::BenchSettingsDialog</name>
    <message>
        <location filename="../../ui/bench_settings_dialog.cpp" line="+112"/>
        <source>Bench constants</source>
        <translation>测试台常数</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+60"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="-59"/>
        <location line="+46"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location line="-45"/>
        <source> °/pulse</source>
        <translation> °/脉冲</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> MHz</source>
        <translation> MHz</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> bit</source>
        <translation> 位</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Table angle read delay</source>
        <translation>转台角度读数延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+2"/>
        <source>  its standard uncertainty</source>
        <translation>  其标准不确定度</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Processing-board delay</source>
        <translation>处理板延迟</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Latitude</source>
        <translation>纬度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro pulse equivalent</source>
        <translation>陀螺脉冲当量</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sampling-board counter</source>
        <translation>采样板计数器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Counter width</source>
        <translation>计数器位宽</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The gyro&apos;s stated scale tolerance: each test point&apos;s gyro/table amplitude ratio, with the gyro&apos;s fitted dynamics taken out, must lie within 1 ± this, or the point is invalid (a wrong pulse equivalent or frame period scales the gyro, not the delay)</source>
        <translation>陀螺声明的标度容差：每个测试点的陀螺/转台幅值比在扣除陀螺拟合出的动态特性后，必须落在 1 ± 此值以内，否则该测试点无效（错误的脉冲当量或帧周期会缩放陀螺读数，而不会改变延迟）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Gyro scale tolerance</source>
        <translation>陀螺标度容差</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>+1 (turns with the table)</source>
        <translation>+1（与转台同向转动）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>−1 (mounted the other way round)</source>
        <translation>−1（反向安装）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Gyro sign, %1 axis</source>
        <translation>陀螺符号，%1 轴</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not stated (found from the data)</source>
        <translation>未声明（由数据判定）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NED: x north, y east, z down</source>
        <translation>NED：x 北，y 东，z 下</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ENU: x east, y north, z up</source>
        <translation>ENU：x 东，y 北，z 上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FRD: x forward, y right, z down</source>
        <translation>FRD：x 前，y 右，z 下</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RFU: x right, y forward, z up</source>
        <translation>RFU：x 右，y 前，z 上</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Where the IMU&apos;s axes point with the table at zero. The Earth rate and gravity the gyros see depend on it; the diagnosis replays the session in it and checks it against the data.</source>
        <translation>转台各轴为零时 IMU 各轴的指向。陀螺敏感到的地球自转角速度和重力取决于它；诊断在该坐标系中回放会话，并用数据检验它。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not stated</source>
        <translation>未声明</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Azimuth of the IMU&apos;s forward axis, from north toward east</source>
        <translation>IMU 前向轴的方位角，自北向东计</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>IMU frame at zero angles</source>
        <translation>零位时的 IMU 坐标系</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  forward axis heading</source>
        <translation>  前向轴方位角</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>IMU delay limit (acceptance)</source>
        <translation>IMU 延迟限值（验收）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>PASS when IMU delay + k·σ &lt; limit (one-sided guarded acceptance, ISO/IEC 17025:2017 §7.8.6); the guard band below the limit is k·σ</source>
        <translation>IMU 延迟 + k·σ &lt; 限值时为合格（单侧保护带验收，ISO/IEC 17025:2017 §7.8.6）；限值以下的保护带为 k·σ</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>maximum false-accept risk 1 − Φ(k) = %1</source>
        <translation>最大误接受风险 1 − Φ(k) = %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>  coverage factor k (PASS: delay + k·σ &lt; limit)</source>
        <translation>  包含因子 k（合格：延迟 + k·σ &lt; 限值）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>IMU delay = measured lag + table read delay; gyro&apos;s own delay = IMU delay − processing-board delay. The pulse equivalent is used only when the board&apos;s stream does not state it; the simulator uses these values for the chain it simulates. The gyro signs, the limit and k are stored with every result: changing them changes no stored verdict; re-analyse a session to store a new result with them.</source>
        <translation>IMU 延迟 = 测得滞后 + 转台读数延迟；陀螺自身延迟 = IMU 延迟 − 处理板延迟。仅当采样板数据流未给出脉冲当量时才使用此处的脉冲当量；仿真器按这些值仿真其链路。陀螺符号、限值和 k 随每个结果一起保存：修改它们不会改变任何已保存的判定；重新分析会话即可按新设置保存新结果。</translation>
    </message>
</context>
<context>
    <name>fog::ui::BodeText</name>
    <message>
        <location filename="../../ui/plot_data/bode_curves.cpp" line="+125"/>
        <source>pure delay</source>
        <translation>纯延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>delay + first-order lag</source>
        <translation>延迟 + 一阶滞后</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>delay + second-order (resonant)</source>
        <translation>延迟 + 二阶（谐振）</translation>
    </message>
</context>
<context>
    <name>fog::ui::BodeView</name>
    <message>
        <location filename="../../ui/bode_view.cpp" line="+45"/>
        <source>%1 axis</source>
        <translation>%1 轴</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>The axis whose response is shown</source>
        <translation>显示其频率响应的轴</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Magnitude of gyro angle / table angle at each test frequency, ±1σ, and the chosen model</source>
        <translation>各测试频率下陀螺角度 / 转台角度的幅值（±1σ）及所选模型</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Phase of gyro angle / table angle (negative: the gyro lags), ±1σ, and the chosen model</source>
        <translation>陀螺角度 / 转台角度的相位（负值：陀螺滞后，±1σ）及所选模型</translation>
    </message>
    <message>
        <location line="+21"/>
        <location line="+176"/>
        <location line="+89"/>
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
    <message>
        <location line="-263"/>
        <source>dB</source>
        <translation>dB</translation>
    </message>
    <message>
        <location line="+22"/>
        <location line="+26"/>
        <source>series</source>
        <translation>序列</translation>
    </message>
    <message>
        <location line="-26"/>
        <source>model</source>
        <translation>模型</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>χ²/dof</source>
        <translation>χ²/自由度</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>AIC</source>
        <translation>AIC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>BIC</source>
        <translation>BIC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>p (fit)</source>
        <translation>p（拟合）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>parameters (± 1σ)</source>
        <translation>参数（± 1σ）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>−3 dB bandwidth</source>
        <translation>−3 dB 带宽</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>group delay</source>
        <translation>群延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>what the points cannot tell</source>
        <translation>数据点无法区分的内容</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>point</source>
        <translation>测试点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>f (Hz)</source>
        <translation>f（Hz）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>|H| (dB) ± 1σ</source>
        <translation>|H| (dB) ± 1σ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>phase (°) ± 1σ</source>
        <translation>相位 (°) ± 1σ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>phase vs motion (°)</source>
        <translation>相对转台运动的相位 (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>U (k = 2), °</source>
        <translation>U (k = 2)，°</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>U (k = 2), ms</source>
        <translation>U (k = 2)，ms</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>lag (ms) ± 1σ</source>
        <translation>滞后 (ms) ± 1σ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The phase against the table&apos;s motion: the phase against the stamped table angle corrected by the table read delay (the bench constant), as a certificate states it</source>
        <translation>相对转台运动的相位：相对带时间戳的转台角度的相位经转台读数延迟（台架常数）修正，即校准证书给出的相位</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Expanded uncertainty of the phase against the table&apos;s motion, k = 2: the point&apos;s phase σ and the table read delay&apos;s uncertainty in quadrature, times 2</source>
        <translation>相对转台运动的相位的扩展不确定度，k = 2：该点相位的 σ 与转台读数延迟的不确定度按方和根合成，再乘以 2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Against the stamped table angle (−ω·lag), as the models are fitted; ±1σ</source>
        <translation>相对带时间戳的转台角度（−ω·滞后），模型即按此拟合；±1σ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>, as a time (U / ω)</source>
        <translation>，以时间表示（U / ω）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Models</source>
        <translation>模型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Points, phase U (k = 2)</source>
        <translation>测试点，相位 U (k = 2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every model fitted to the points</source>
        <translation>对这些测试点拟合的每个模型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every point with its phase against the table&apos;s motion and that phase&apos;s expanded uncertainty (k = 2), the table read delay&apos;s uncertainty in the budget</source>
        <translation>每个测试点相对转台运动的相位及其扩展不确定度 (k = 2)，不确定度预算中包含转台读数延迟的不确定度</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>No frequency response yet.</source>
        <translation>尚无频率响应。</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>not admissible: %1</source>
        <translation>不可接受：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (rejected)</source>
        <translation>%1（拒绝）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>none (flat)</source>
        <translation>无（平坦）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 at %2 Hz</source>
        <translation>%1（%2 Hz 处）</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+86"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location line="-78"/>
        <source>The probability of a χ² this large were the model true: below %1 the model is rejected and never chosen</source>
        <translation>若模型成立，χ² 不小于此值的概率：低于 %1 时模型被拒绝，绝不被选中</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The model chosen: the lowest AIC; a larger model over a simpler one it contains only when it lowers χ² by 3σ for its extra parameters (9 for one, 11.83 for two)</source>
        <translation>所选模型：AIC 最低；较大的模型仅当其使 χ² 比它所包含的较简单模型降低 3σ（多 1 个参数为 9，多 2 个为 11.83）时才选它</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>U (k = %1) = %2° = %3 ms: the fit&apos;s σ %4° and the table read delay&apos;s %5° (its uncertainty %6 ms of the read delay %7 ms) in quadrature</source>
        <translation>U (k = %1) = %2° = %3 ms：拟合的 σ %4° 与转台读数延迟的 %5°（读数延迟 %7 ms 的不确定度 %6 ms）按方和根合成</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>; &lt;b&gt;%1&lt;/b&gt; (chosen): group delay at %2 Hz &lt;b&gt;%3&lt;/b&gt;</source>
        <translation>；&lt;b&gt;%1&lt;/b&gt;（所选）：%2 Hz 处群延迟 &lt;b&gt;%3&lt;/b&gt;</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>; &lt;b&gt;no model fits&lt;/b&gt;: the points alone are the response</source>
        <translation>；&lt;b&gt;没有模型拟合&lt;/b&gt;：响应仅由测量点给出</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>model (chosen)</source>
        <translation>模型（所选）</translation>
    </message>
    <message>
        <location line="-26"/>
        <source>%1%2 points, %3 – %4 Hz</source>
        <translation>%1%2 个点，%3 – %4 Hz</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>, −3 dB bandwidth %1</source>
        <translation>，−3 dB 带宽 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (extrapolated beyond the highest point, %1 Hz)</source>
        <translation>（外推至最高测试点 %1 Hz 之外）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>model left out: %1</source>
        <translation>未拟合的模型：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>measured ±1σ</source>
        <translation>测量值 ±1σ</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+1"/>
        <source>%1 model</source>
        <translation>%1 模型</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 − %2</source>
        <translation>%1 − %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 and %2 share no test frequency (within 0.5 %): no difference is drawn.</source>
        <translation>%1 与 %2 没有共同的测试频率（相差 0.5 % 以内）：不绘制差值。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>|H| (dB)</source>
        <translation>|H|（dB）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frequency (Hz)</source>
        <translation>频率（Hz）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>phase (°)</source>
        <translation>相位（°）</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 axis: %2</source>
        <translation>%1 轴：%2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> (no response: %1)</source>
        <translation>（无频率响应：%1）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No frequency response: it needs two or more test points of one axis that passed their checks, and this result has %1. The plan preset &quot;Frequency response&quot; (run --preset response) records 20 frequencies of the X axis.</source>
        <translation>无频率响应：需要同一轴上两个或以上通过检查的测试点，而此结果有 %1。计划预设“频率响应”（run --preset response）记录 X 轴的 20 个频率。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>none</source>
        <translation>无</translation>
    </message>
</context>
<context>
    <name>fog::ui::CommandedMotionTable</name>
    <message>
        <location filename="../../ui/commanded_motion.cpp" line="+51"/>
        <source>Point</source>
        <translation>测试点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Axis</source>
        <translation>轴</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>amplitude %1° is beyond the table&apos;s %2° on %3</source>
        <translation>幅值 %1° 超出转台 %3 轴的 %2°</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the angle leaves the table&apos;s ±%1°</source>
        <translation>角度超出转台的 ±%1°</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>±%1</source>
        <translation>±%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>peak rate beyond the table&apos;s %1 °/s on %2</source>
        <translation>峰值角速率超出转台 %2 轴的 %1 °/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>peak acceleration beyond the table&apos;s %1 °/s² on %2</source>
        <translation>峰值角加速度超出转台 %2 轴的 %1 °/s²</translation>
    </message>
    <message>
        <location line="-80"/>
        <source>the simulator&apos;s turntable</source>
        <translation>仿真器的转台</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>amplitude %1°, frequency %2 Hz, peak rate %3 °/s, peak acceleration %4 °/s²</source>
        <translation>幅值 %1°，频率 %2 Hz，峰值角速率 %3 °/s，峰值角加速度 %4 °/s²</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Frequency
(Hz)</source>
        <translation>频率
(Hz)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Angle
(°)</source>
        <translation>角度
(°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Peak rate
(°/s)</source>
        <translation>峰值角速率
(°/s)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Peak accel.
(°/s²)</source>
        <translation>峰值角加速度
(°/s²)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>per axis: %1</source>
        <translation>每轴：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; </source>
        <translation>；</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Limits of %1, %2; angle within ±%3°. Red: beyond a limit.</source>
        <translation>%1 的限值，%2；角度在 ±%3° 以内。红色：超出限值。</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>frequency beyond the table&apos;s %1 Hz on %2</source>
        <translation>频率超出转台 %2 轴的 %1 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at rest</source>
        <translation>静止</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+4"/>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
</context>
<context>
    <name>fog::ui::CompareView</name>
    <message>
        <location filename="../../ui/compare_view.cpp" line="+132"/>
        <source>session</source>
        <translation>会话</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>recorded (UTC)</source>
        <translation>记录时间 (UTC)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>IMU</source>
        <translation>IMU</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>result compared</source>
        <translation>所比较的结果</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>loading …</source>
        <translation>正在加载 …</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Compare</source>
        <translation>比较</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>against</source>
        <translation>相对于</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Test point</source>
        <translation>测试点</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export CSV…</source>
        <translation>导出 CSV…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the rows of the comparison (each test point&apos;s IMU delay in A and B, B − A, its σ and |B − A|/σ) as a CSV file</source>
        <translation>将比较的各行（每个测试点在 A 和 B 中的 IMU 延迟、B − A、其 σ 及 |B − A|/σ）保存为 CSV 文件</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+4"/>
        <source>Export the comparison (CSV)</source>
        <translation>导出比较结果（CSV）</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>CSV file (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The comparison was not saved</source>
        <translation>比较结果未保存</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+153"/>
        <source>test point</source>
        <translation>测试点</translation>
    </message>
    <message>
        <location line="-147"/>
        <source>Zero crossing of A and B</source>
        <translation>A 与 B 的过零点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>(angle − offset) / amplitude</source>
        <translation>(角度 − 偏置) / 幅值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>time from each session&apos;s table-fit zero crossing (ms)</source>
        <translation>距各会话转台拟合过零点的时间 (ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lag against swing frequency</source>
        <translation>滞后随摆动频率的变化</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>swing frequency (Hz)</source>
        <translation>摆动频率 (Hz)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>lag (ms), ±1σ</source>
        <translation>滞后 (ms)，±1σ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>IMU delay against the recording date</source>
        <translation>IMU 延迟随记录日期的变化</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>recorded</source>
        <translation>记录时间</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>IMU delay (ms), ±1σ</source>
        <translation>IMU 延迟 (ms)，±1σ</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Zero crossing</source>
        <translation>过零点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lag vs frequency</source>
        <translation>滞后与频率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trend</source>
        <translation>趋势</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Frequency response</source>
        <translation>频率响应</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Loading the sessions …</source>
        <translation>正在加载会话 …</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>unreadable: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>no delay: %1</source>
        <translation>无延迟：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>result %1 of %2; table read %3 ± %4 ms, board %5 ms</source>
        <translation>结果 %1/%2；转台读数延迟 %3 ± %4 ms，板卡 %5 ms</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (stored, limit %2 ms) · %3</source>
        <translation>%1（已保存，限值 %2 ms）· %3</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 (not stored, limit %2 ms) · %3</source>
        <translation>%1（未保存，限值 %2 ms）· %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> · this version&apos;s analysis differs from the stored result; re-analyse to store it</source>
        <translation> · 本版本的分析与已保存结果不同；重新分析即可保存</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>%1 against %2: %3 test point(s) compared, %4 differ by more than 2σ.</source>
        <translation>%1 对比 %2：比较了 %3 个测试点，其中 %4 个相差超过 2σ。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 test point(s) in both are not compared: a delay not vouched for (INVALID, INCOMPLETE) is never subtracted.</source>
        <translation>两者共有的 %1 个测试点未比较：不可担保的延迟（无效、不完整）从不参与相减。</translation>
    </message>
    <message>
        <location line="-75"/>
        <source>There is no comparison to export.</source>
        <translation>没有可导出的比较结果。</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+149"/>
        <source>Choose two different sessions.</source>
        <translation>请选择两个不同的会话。</translation>
    </message>
    <message>
        <location line="-148"/>
        <location line="+149"/>
        <source>Session %1 or %2 has no delay result to compare.</source>
        <translation>会话 %1 或 %2 没有可比较的延迟结果。</translation>
    </message>
    <message>
        <location line="-141"/>
        <location line="+1"/>
        <source>%1: IMU delay (ms)</source>
        <translation>%1：IMU 延迟 (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 − %2 (ms)</source>
        <translation>%1 − %2 (ms)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>±σ (ms)</source>
        <translation>±σ (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>|%1 − %2|/σ</source>
        <translation>|%1 − %2|/σ</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 ± %2</source>
        <translation>%1 ± %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>differs (more than 2σ)</source>
        <translation>有差异（超过 2σ）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>consistent (within 2σ)</source>
        <translation>一致（2σ 以内）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not compared: %1&apos;s delay is refused (%2)</source>
        <translation>未比较：%1 的延迟被拒绝（%2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>only in %1</source>
        <translation>仅在 %1 中</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Both used the same table read delay: its uncertainty cancels in the difference, σ combines the two lags&apos; uncertainties.</source>
        <translation>两者使用相同的转台读数延迟：其不确定度在差值中抵消，σ 由两个滞后的不确定度合成。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The table read delays differ: σ combines the two IMU delays&apos; uncertainties.</source>
        <translation>转台读数延迟不同：σ 由两个 IMU 延迟的不确定度合成。</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>%1: table</source>
        <translation>%1：转台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: gyro</source>
        <translation>%1：陀螺</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: gyro fit</source>
        <translation>%1：陀螺拟合</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>a frequency response of the %1 axis</source>
        <translation>%1 轴的频率响应</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 and %2 have no axis with a frequency response in common. %1: %3 %2: %4</source>
        <translation>%1 与 %2 没有共同具有频率响应的轴。%1：%3 %2：%4</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>%1: refused (INVALID or INCOMPLETE)</source>
        <translation>%1：被拒绝（无效或不完整）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>IMU delay against the recording date (IMU not named)</source>
        <translation>IMU 延迟随记录日期的变化（未填写 IMU）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU delay of %1 against the recording date</source>
        <translation>%1 的 IMU 延迟随记录日期的变化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU delay against the recording date (%1 IMUs: %2)</source>
        <translation>IMU 延迟随记录日期的变化（%1 个 IMU：%2）</translation>
    </message>
</context>
<context>
    <name>fog::ui::ConfigureView</name>
    <message>
        <location filename="../../ui/configure_view.cpp" line="+159"/>
        <source>Test plan</source>
        <translation>测试计划</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Commanded table motion</source>
        <translation>转台指令运动</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+28"/>
        <source>Source</source>
        <translation>数据源</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>Built-in simulator</source>
        <translation>内置仿真器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replay of a session</source>
        <translation>回放会话</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial sampling board</source>
        <translation>串口采样板</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Real time</source>
        <translation>实时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5× real time</source>
        <translation>5 倍实时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>20× real time</source>
        <translation>20 倍实时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As fast as possible</source>
        <translation>尽可能快</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Simulator seed: the same seed gives the same data</source>
        <translation>仿真器种子：相同种子产生相同数据</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>session file (.fbs) to replay</source>
        <translation>要回放的会话文件（.fbs）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Seed</source>
        <translation>种子</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pace</source>
        <translation>速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replay</source>
        <translation>回放</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The sampling board&apos;s serial port</source>
        <translation>采样板的串口</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Rescan</source>
        <translation>重新扫描</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Serial port</source>
        <translation>串口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Not driven (the board&apos;s own plan)</source>
        <translation>不驱动（采集板自己的计划）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remote controller</source>
        <translation>远程控制器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual (the operator sets it)</source>
        <translation>手动（由操作员设置）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remote: the bench commands the turntable controller through the plan; manual: the bench tells you what to set and records once the table angle shows it</source>
        <translation>远程：测试台按计划指令转台控制器；手动：测试台告诉您如何设置，并在转台角度显示出该运动后开始记录</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>tcp:HOST:PORT or device</source>
        <translation>tcp:主机:端口 或设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The turntable controller: tcp:HOST:PORT (numeric address) or its serial device</source>
        <translation>转台控制器：tcp:主机:端口（数字地址）或其串口设备</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Turntable</source>
        <translation>转台</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Session</source>
        <translation>会话</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Record a session file (crash-safe)</source>
        <translation>记录会话文件（防崩溃）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Choose…</source>
        <translation>选择…</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Folder</source>
        <translation>文件夹</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>IMU model</source>
        <translation>IMU 型号</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Bench id</source>
        <translation>工位编号</translation>
    </message>
    <message>
        <location line="-169"/>
        <source>the simulator&apos;s turntable</source>
        <translation>仿真器的转台</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the connected controller %1</source>
        <translation>已连接的控制器 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the simulator&apos;s turntable (no controller connected: connect it in Table controls to check the plan against its own limits)</source>
        <translation>仿真器的转台（未连接控制器：在“转台控制”中连接后，按其自身限值检查计划）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the simulator&apos;s turntable (the bench does not command this table and cannot read its limits)</source>
        <translation>仿真器的转台（测试台不指令此转台，无法读取其限值）</translation>
    </message>
    <message>
        <location line="+167"/>
        <source>Lot</source>
        <translation>批次</translation>
    </message>
    <message>
        <location line="+121"/>
        <source>table read delay %1 ms · board delay %2 ms · latitude %3°
pulse equivalent %4° · counter %5 MHz / %6 bit
gyro signs %7 · IMU frame %8</source>
        <translation>转台读数延迟 %1 ms · 处理板延迟 %2 ms · 纬度 %3°
脉冲当量 %4° · 计数器 %5 MHz / %6 位
陀螺符号 %7 · IMU 坐标系 %8</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>not stated</source>
        <translation>未声明</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU frame: %1</source>
        <translation>IMU 坐标系：%1</translation>
    </message>
    <message>
        <location line="-133"/>
        <source>IMU serial</source>
        <translation>IMU 序列号</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Notes</source>
        <translation>备注</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Bench constants</source>
        <translation>测试台常数</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Edit…</source>
        <translation>编辑…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit the bench constants</source>
        <translation>编辑测试台常数</translation>
    </message>
    <message>
        <location line="-129"/>
        <source>Session to replay</source>
        <translation>要回放的会话</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fogbench sessions (*.fbs)</source>
        <translation>fogbench 会话 (*.fbs)</translation>
    </message>
    <message>
        <location line="+106"/>
        <source>Session folder</source>
        <translation>会话文件夹</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>%1× real time</source>
        <translation>%1 倍实时</translation>
    </message>
</context>
<context>
    <name>fog::ui::DeltaPicker</name>
    <message>
        <location filename="../../ui/plots/delta_picker.cpp" line="+29"/>
        <source>t = %1 s, %2 %3</source>
        <translation>t = %1 s，%2 %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>
Δt = %1, Δ = %2 %3</source>
        <translation>
Δt = %1，Δ = %2 %3</translation>
    </message>
</context>
<context>
    <name>fog::ui::DiagnosisView</name>
    <message>
        <location filename="../../ui/diagnosis_view.cpp" line="+136"/>
        <source>Test point</source>
        <translation>测试点</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>IMU bias instability known:</source>
        <translation>已知 IMU 零偏不稳定性：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The IMU&apos;s bias instability from its static noise test (Noise view: Markov sigma and correlation time). Unchecked, the diagnosis assumes %1 °/h over %2 s, and a bias drift or step smaller than such a wander is not resolved.</source>
        <translation>IMU 静态噪声测试得到的零偏不稳定性（噪声视图：马尔可夫 σ 与相关时间）。不勾选时，诊断假定 %1 °/h、相关时间 %2 s，小于这种漂移的零偏漂移或阶跃无法分辨。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source> °/h</source>
        <translation> °/h</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>over </source>
        <translation>相关时间 </translation>
    </message>
    <message>
        <location line="+1"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop the diagnosis; nothing is kept of it</source>
        <translation>停止诊断；不保留其任何结果</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cancelling …</source>
        <translation>正在取消 …</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Gyro residual: real and simulated</source>
        <translation>陀螺残差：实测与仿真</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>time from the record&apos;s middle (s)</source>
        <translation>相对记录中点的时间 (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>residual (arcsec)</source>
        <translation>残差（角秒）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gap map: z against the simulator&apos;s spread</source>
        <translation>差异图：相对仿真离散度的 z 值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Residual spectrum</source>
        <translation>残差频谱</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>harmonic of the swing frequency</source>
        <translation>摆动频率的谐波次数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relative to the fundamental (ppm)</source>
        <translation>相对基波 (ppm)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+359"/>
        <source>Held-out shrink per candidate effect</source>
        <translation>各候选效应在留出数据上的差异缩减</translation>
    </message>
    <message>
        <location line="-359"/>
        <source>held-out gap closed (%)</source>
        <translation>留出数据差异缩减 (%)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>″</source>
        <translation>″</translation>
    </message>
    <message>
        <location line="-121"/>
        <source>Run or open a session, then press Diagnose in the Results view.</source>
        <translation>请运行或打开一个会话，然后在“结果”视图中按“诊断”。</translation>
    </message>
    <message>
        <location line="+195"/>
        <source>calibrating the replay to the session</source>
        <translation>按会话标定回放</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>replaying the session in the simulator</source>
        <translation>在仿真器中回放会话</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mapping the gap</source>
        <translation>绘制差异图</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fitting the candidate effects</source>
        <translation>拟合候选效应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refining the best effects</source>
        <translation>细化最佳效应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>trying pairs of effects</source>
        <translation>尝试效应组合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reaching the verdict</source>
        <translation>得出结论</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>starting …</source>
        <translation>正在开始 …</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;b&gt;Diagnosing %1&lt;/b&gt;: replaying it in the simulator and comparing.</source>
        <translation>&lt;b&gt;正在诊断 %1&lt;/b&gt;：在仿真器中回放并比较。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diagnosing %1 …
The plots appear when the diagnosis is done.</source>
        <translation>正在诊断 %1 …
诊断完成后显示图表。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&lt;b&gt;Diagnosis cancelled&lt;/b&gt;: %1 has no diagnosis.</source>
        <translation>&lt;b&gt;诊断已取消&lt;/b&gt;：%1 没有诊断结果。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diagnosis cancelled.
Press Diagnose in the Results view to start it again.</source>
        <translation>诊断已取消。
在“结果”视图中按“诊断”可重新开始。</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 %2 → %3   </source>
        <translation>%1 %2 → %3   </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;b&gt;%1 — verdict: %2&lt;/b&gt;&lt;br&gt;%3&lt;br&gt;gap per channel (rms z, 1 = within the simulator&apos;s spread), before → after: %4</source>
        <translation>&lt;b&gt;%1 —— 结论：%2&lt;/b&gt;&lt;br&gt;%3&lt;br&gt;各通道差异（z 的均方根，1 = 在仿真离散度之内），之前 → 之后：%4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>verdict: %1 (the JSON&apos;s &quot;verdict&quot;)</source>
        <translation>判定：%1（JSON 中的 &quot;verdict&quot;）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: %2 axis, %3 Hz</source>
        <translation>%1：%2 轴，%3 Hz</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>recorded</source>
        <translation>实测</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>simulated (replay)</source>
        <translation>仿真（回放）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>table, recorded</source>
        <translation>转台，实测</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>table, simulated</source>
        <translation>转台，仿真</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro, recorded</source>
        <translation>陀螺，实测</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>gyro, simulated</source>
        <translation>陀螺，仿真</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>P%1 S%2</source>
        <translation>点%1 段%2</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>P test point, S segment</source>
        <translation>点：测试点，段：分段</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Held-out shrink: the %1 best-ranked of %2 effects (all in the text below)</source>
        <translation>留出数据差异缩减：%2 个效应中排名前 %1 的（全部见下方文本）</translation>
    </message>
</context>
<context>
    <name>fog::ui::ImportDialog</name>
    <message>
        <location filename="../../ui/import_dialog.cpp" line="+26"/>
        <source>Import CSV data</source>
        <translation>导入 CSV 数据</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>From %1</source>
        <translation>来自 %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>as metadata.json states (increments need none)</source>
        <translation>按 metadata.json 所述（增量无需此项）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frame average: each rate is its frame&apos;s increment / frame period</source>
        <translation>帧平均：每个角速率为该帧增量 / 帧周期</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sample at stamp: each rate is the rate at its row&apos;s time</source>
        <translation>时标采样：每个角速率为该行时刻的瞬时角速率</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>How a gyro file of rates (x_rate_deg_s …) was sampled. The choice moves the delay by about half a frame, so it is never guessed; a metadata.json that states another one is refused.</source>
        <translation>角速率陀螺文件（x_rate_deg_s …）的采样方式。该选择会使延迟移动约半帧，因此从不猜测；metadata.json 中写明另一种方式时将被拒绝。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gyro rates</source>
        <translation>陀螺角速率</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>as metadata.json states</source>
        <translation>按 metadata.json 所述</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The IMU&apos;s own frame period, for rates averaged over a frame</source>
        <translation>IMU 自身的帧周期，用于按帧平均的角速率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU frame period</source>
        <translation>IMU 帧周期</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the files&apos; test points</source>
        <translation>文件中的测试点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut one continuous recording at the steady swings found</source>
        <translation>将一段连续记录按找到的稳定摆动切分</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cut one continuous recording at the windows given</source>
        <translation>将一段连续记录按给定的时间窗切分</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test points</source>
        <translation>测试点</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>start-end in seconds, e.g. 12.5-42,50-80.25</source>
        <translation>起止时间（秒），例如 12.5-42,50-80.25</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Swing windows</source>
        <translation>摆动时间窗</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Import</source>
        <translation>导入</translation>
    </message>
</context>
<context>
    <name>fog::ui::LiveView</name>
    <message>
        <location filename="../../ui/live_view.cpp" line="+61"/>
        <source>board time (s)</source>
        <translation>采样板时间 (s)</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>No run yet: configure a plan and press Run.</source>
        <translation>尚未运行：请配置测试计划并按“运行”。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Window</source>
        <translation>窗口</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How much of the stream the plots show while following</source>
        <translation>跟随时曲线显示的数据时长</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Follow live</source>
        <translation>跟随实时</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Turntable</source>
        <translation>转台</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Driver</source>
        <translation>驱动</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mode</source>
        <translation>模式</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Faults / interlocks</source>
        <translation>故障 / 联锁</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Commanded</source>
        <translation>指令</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Measured</source>
        <translation>实测</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+249"/>
        <source>Step</source>
        <translation>步骤</translation>
    </message>
    <message>
        <location line="-239"/>
        <source>Turntable angle</source>
        <translation>转台角度</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+3"/>
        <source>angle (°)</source>
        <translation>角度 (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Gyro angle (integrated, bias + Earth rate removed)</source>
        <translation>陀螺角度（积分，已去除零偏 + 地球自转）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Test point</source>
        <translation>测试点</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Plan</source>
        <translation>计划</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Waiting for the first frames …</source>
        <translation>等待首批数据帧 …</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>run ended</source>
        <translation>运行结束</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>positioning</source>
        <translation>定位中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>swinging</source>
        <translation>摆动中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopping</source>
        <translation>停止中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>emergency stop</source>
        <translation>急停</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+59"/>
        <source>at rest (run over)</source>
        <translation>静止（运行结束）</translation>
    </message>
    <message>
        <location line="-57"/>
        <source>swinging %1</source>
        <translation>%1 轴摆动中</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+62"/>
        <source>at rest (plan done)</source>
        <translation>静止（计划完成）</translation>
    </message>
    <message>
        <location line="-60"/>
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location line="+133"/>
        <source>board idle</source>
        <translation>采集板空闲</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>— (after two periods of recording)</source>
        <translation>—（记录两个周期后显示）</translation>
    </message>
    <message>
        <location line="-180"/>
        <location line="+30"/>
        <location line="+72"/>
        <source>at rest</source>
        <translation>静止</translation>
    </message>
    <message>
        <location line="-64"/>
        <source>%1 at rest at %2°</source>
        <translation>%1 轴静止于 %2°</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 Hz, %3° about %4°</source>
        <translation>%1 轴 %2 Hz，%3°，中心 %4°</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+26"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 Hz, %3°</source>
        <translation>%1 轴 %2 Hz，%3°</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+39"/>
        <source>none reported</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>NOT seen at rest: check the table</source>
        <translation>未确认静止：请检查转台</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>connecting</source>
        <translation>连接中</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>set by the operator; checking the swing</source>
        <translation>由操作员设置；正在检查摆动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set by the operator; swing verified</source>
        <translation>由操作员设置；摆动已确认</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>set by the operator</source>
        <translation>由操作员设置</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 %2 (%3°, %4 °/s)</source>
        <translation>%2 轴%1（%3°，%4 °/s）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>interlock open</source>
        <translation>联锁断开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>emergency stop engaged</source>
        <translation>急停已触发</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heartbeat lost (the controller stopped the table)</source>
        <translation>心跳丢失（控制器已停止转台）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>run stopped: %1</source>
        <translation>运行已停止：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not readable (manual)</source>
        <translation>无法读取（手动）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>plan unknown</source>
        <translation>计划未知</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>as fast as possible</source>
        <translation>尽可能快</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 left of %2</source>
        <translation>剩余 %1 / 共 %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>settling</source>
        <translation>稳定中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recording</source>
        <translation>记录中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>t = %1 s · %2</source>
        <translation>t = %1 s · %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Test point %1 of %2 · %3 axis, %4 Hz · %5 · t = %6 s · gyro trend %7 °/h</source>
        <translation>测试点 %1 / %2 · %3 轴，%4 Hz · %5 · t = %6 s · 陀螺趋势 %7 °/h</translation>
    </message>
</context>
<context>
    <name>fog::ui::MainWindow</name>
    <message>
        <location filename="../../ui/main_window.cpp" line="+154"/>
        <location line="+1060"/>
        <source>fogbench %1 — FOG IMU delay bench</source>
        <translation>fogbench %1 —— 光纤陀螺 IMU 延迟测试台</translation>
    </message>
    <message>
        <location line="-1052"/>
        <source>Configure</source>
        <translation>配置</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Live</source>
        <translation>实时</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Results</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Sessions</source>
        <translation>会话</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+1129"/>
        <source>Diagnosis</source>
        <translation>诊断</translation>
    </message>
    <message>
        <location line="-1126"/>
        <source>Noise</source>
        <translation>噪声</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Configure a plan and press Run.</source>
        <translation>请配置测试计划并按“运行”。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&lt;h3&gt;fogbench %1&lt;/h3&gt;&lt;p&gt;Fiber-optic gyro IMU delay test bench: swing the IMU on a turntable, stamp table angle and gyro increments with one counter, fit sinusoids to both and turn their phase difference into the IMU&apos;s delay, with its uncertainty.&lt;/p&gt;&lt;p&gt;Built with Qt %2 (running on %3) and Qwt %4.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;fogbench %1&lt;/h3&gt;&lt;p&gt;光纤陀螺 IMU 延迟测试台：转台带动 IMU 摆动，用同一计数器为转台角度和陀螺增量打时间戳，对两者拟合正弦，并将相位差换算为 IMU 延迟及其不确定度。&lt;/p&gt;&lt;p&gt;基于 Qt %2（运行于 %3）和 Qwt %4 构建。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+176"/>
        <source>&amp;Bench constants…</source>
        <translation>测试台常数(&amp;B)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>System default</source>
        <translation>跟随系统</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;About fogbench</source>
        <translation>关于 fogbench(&amp;A)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>About fogbench</source>
        <translation>关于 fogbench</translation>
    </message>
    <message>
        <location line="-206"/>
        <location line="+3"/>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <location line="-101"/>
        <source>Units</source>
        <translation>单元</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+130"/>
        <source>End the run now; everything received so far is kept and analysed</source>
        <translation>立即结束运行；已接收的全部数据都会保留并分析</translation>
    </message>
    <message>
        <location line="-64"/>
        <source>Emergency stop: sent on a connection of its own, and by the run&apos;s table driver at its next step; the run stops.</source>
        <translation>急停：已通过独立连接发送，运行的转台驱动也会在其下一步发送；运行停止。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Emergency stop sent to the table; the table panel says what came of it.</source>
        <translation>急停指令已发送至转台；结果见转台面板。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open session…</source>
        <translation>打开会话(&amp;O)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+779"/>
        <source>Open session</source>
        <translation>打开会话</translation>
    </message>
    <message>
        <location line="-778"/>
        <source>fogbench sessions (*.fbs);;All files (*)</source>
        <translation>fogbench 会话 (*.fbs);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open &amp;recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Load test plan…</source>
        <translation>载入测试计划(&amp;L)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+4"/>
        <source>Load test plan</source>
        <translation>载入测试计划</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>Test plans (*.json);;All files (*)</source>
        <translation>测试计划 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot load the test plan %1</source>
        <translation>无法载入测试计划 %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Save test plan…</source>
        <translation>保存测试计划(&amp;S)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+5"/>
        <source>Save test plan</source>
        <translation>保存测试计划</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>Test plans (*.json)</source>
        <translation>测试计划 (*.json)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot save the test plan as %1</source>
        <translation>无法将测试计划保存为 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Import CSV data…</source>
        <translation>导入 CSV 数据(&amp;I)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Folder with metadata.json, table.csv, gyro.csv</source>
        <translation>包含 metadata.json、table.csv、gyro.csv 的文件夹</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open the &amp;export folder</source>
        <translation>打开导出文件夹(&amp;E)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the folder of the last export (plot or report)</source>
        <translation>显示最近一次导出（曲线或报告）所在的文件夹</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+1"/>
        <source>&amp;Run</source>
        <translation>运行(&amp;R)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Diagnose the shown result</source>
        <translation>诊断当前结果(&amp;D)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Configure</source>
        <translation>配置(&amp;C)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Live</source>
        <translation>实时(&amp;L)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Results</source>
        <translation>结果(&amp;R)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Sessions</source>
        <translation>会话(&amp;S)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Units</source>
        <translation>单元(&amp;U)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Diagnosis</source>
        <translation>诊断(&amp;D)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Noise</source>
        <translation>噪声(&amp;N)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&amp;Tools</source>
        <translation>工具(&amp;T)</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>&amp;Shortcuts</source>
        <translation>快捷键(&amp;S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shortcuts</source>
        <translation>快捷键</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run: F5 or Ctrl+R
Stop: Shift+F5 or Ctrl+.
Diagnose the shown result: Ctrl+D
Re-analyse the shown session: Ctrl+Shift+R
Open a session: Ctrl+O
Load a test plan: Ctrl+L
Save the test plan: Ctrl+S
Views: Ctrl+1 … Ctrl+7
Quit: Ctrl+Q
Plots: wheel zooms, drag pans, double-click shows all, click sets cursors A/B</source>
        <translation>运行：F5 或 Ctrl+R
停止：Shift+F5 或 Ctrl+.
诊断所显示的结果：Ctrl+D
重新分析所显示的会话：Ctrl+Shift+R
打开会话：Ctrl+O
载入测试计划：Ctrl+L
保存测试计划：Ctrl+S
视图：Ctrl+1 … Ctrl+7
退出：Ctrl+Q
曲线图：滚轮缩放，拖动平移，双击显示全部，单击设置光标 A/B</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>(none yet)</source>
        <translation>（暂无）</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Test plan loaded from %1</source>
        <translation>已从 %1 载入测试计划</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Test plan saved as %1</source>
        <translation>测试计划已保存为 %1</translation>
    </message>
    <message>
        <location line="+127"/>
        <source>Saved %1 — File ▸ Open the export folder shows it</source>
        <translation>已保存 %1 —— “文件 ▸ 打开导出文件夹”可查看</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Open the export folder</source>
        <translation>打开导出文件夹</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cannot open the folder %1</source>
        <translation>无法打开文件夹 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No file manager answered; open the folder by hand: %1</source>
        <translation>没有文件管理器响应；请手动打开该文件夹：%1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>A run is under way</source>
        <translation>运行正在进行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A run is under way. Stop it and close fogbench?</source>
        <translation>运行正在进行。停止运行并关闭 fogbench？</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Stopping brings the table to rest and keeps everything received so far in the session file, marked incomplete; fogbench closes once the table is at rest.</source>
        <translation>停止会使转台静止，并把目前收到的全部数据保存在会话文件中（标记为不完整）；转台静止后 fogbench 关闭。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stopping keeps everything received so far in the session file, marked incomplete.</source>
        <translation>停止后，已接收的全部数据保留在会话文件中，并标记为未完成。</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Stop the run and close</source>
        <translation>停止运行并关闭</translation>
    </message>
    <message>
        <location line="-482"/>
        <source>Table</source>
        <translation>转台</translation>
    </message>
    <message>
        <location line="+99"/>
        <source>EMERGENCY STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Stop every axis of the table at once (latched at the controller)</source>
        <translation>立即停止转台所有轴（在控制器处锁定）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> (View ▸ Table controls)</source>
        <translation>（视图 ▸ 转台控制）</translation>
    </message>
    <message>
        <location line="-10"/>
        <location line="+30"/>
        <source>Emergency stop</source>
        <translation>急停</translation>
    </message>
    <message>
        <location line="-30"/>
        <location line="+30"/>
        <source>The emergency stop failed</source>
        <translation>急停失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No table connection is open: neither a run drives the table nor is the table panel connected. Use the controller&apos;s own emergency stop.</source>
        <translation>没有打开的转台连接：既没有运行在驱动转台，转台面板也未连接。请使用控制器自身的急停。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Emergency stop: the run&apos;s table driver sends it at its next step; the run stops.</source>
        <translation>急停：运行的转台驱动在其下一步发送急停；运行停止。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> The table panel&apos;s connection failed: %1</source>
        <translation> 转台面板的连接失败：%1</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>Re-&amp;analyse the shown session</source>
        <translation>重新分析所显示的会话(&amp;A)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open a session first: a re-analysis is stored in the session it analyses.</source>
        <translation>请先打开一个会话：重新分析的结果保存在所分析的会话中。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&amp;Table controls</source>
        <translation>转台控制(&amp;T)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The language can be changed once the run or the diagnosis has ended.</source>
        <translation>运行或诊断结束后才能更改语言。</translation>
    </message>
    <message>
        <location line="+215"/>
        <source>Keep running</source>
        <translation>继续运行</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>a run is under way</source>
        <translation>正在运行</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>choose the session file to replay</source>
        <translation>请选择要回放的会话文件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>choose the sampling board&apos;s serial port</source>
        <translation>请选择采样板的串口</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>give the turntable controller&apos;s address (tcp:HOST:PORT or its serial device)</source>
        <translation>请给出转台控制器的地址（tcp:主机:端口 或其串口设备）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a driven table swings in real time: choose a pace (real time for a real table)</source>
        <translation>受驱动的转台按实时摆动：请选择速度（真实转台选实时）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start the run</source>
        <translation>开始运行</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cannot run: %1</source>
        <translation>无法运行：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;span style=&apos;color:#b00000&apos;&gt;Cannot run: %1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b00000&apos;&gt;无法运行：%1&lt;/span&gt;</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>the baud rate must be a whole number</source>
        <translation>波特率必须是整数</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>cannot create the session folder &apos;%1&apos;; choose another one</source>
        <translation>无法创建会话文件夹“%1”；请另选一个</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>simulator, seed %1, %2</source>
        <translation>仿真器，种子 %1，%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>as fast as possible</source>
        <translation>尽可能快</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>real time</source>
        <translation>实时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1× real time</source>
        <translation>%1 倍实时</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>manual (the operator sets the controller)</source>
        <translation>手动（由操作员设置控制器）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>remote controller %1</source>
        <translation>远程控制器 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>simulator (simulated turntable)</source>
        <translation>仿真器（仿真转台）</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Running: %1 …</source>
        <translation>运行中：%1 …</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Stopping: bringing the table to rest; everything received so far is kept …</source>
        <translation>正在停止：使转台静止；目前收到的全部数据均已保留 …</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopping: everything received so far is kept …</source>
        <translation>正在停止：已接收的数据全部保留 …</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>No data from the source for %1 s — check the connection</source>
        <translation>数据源已 %1 s 无数据——请检查连接</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>frames: %1 · checksum failures: %2 · lost: %3 · duplicates: %4</source>
        <translation>帧：%1 · 校验失败：%2 · 丢失：%3 · 重复：%4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>frames: %1 table · %2 IMU · %3 status  ·  checksum failures: %4  ·  lost: %5  ·  duplicates: %6</source>
        <translation>帧：转台 %1 · IMU %2 · 状态 %3  ·  校验失败：%4  ·  丢失：%5  ·  重复：%6</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> · display skipped %1</source>
        <translation> · 显示跳过 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  ·  display skipped %1 frames (all recorded)</source>
        <translation>  ·  显示跳过 %1 帧（全部已记录）</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Run incomplete (%1); </source>
        <translation>运行未完成（%1）；</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run done in %1; </source>
        <translation>运行完成，用时 %1；</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 test point(s) analysed, %2 without a delay</source>
        <translation>已分析 %1 个测试点，%2 个未得到延迟</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no delay: %1</source>
        <translation>无延迟结果：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>. Saved as %1</source>
        <translation>。已保存为 %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>. WARNING: the table was not seen at rest at the end; check it</source>
        <translation>。警告：结束时未确认转台静止，请检查</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Check the turntable</source>
        <translation>检查转台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The table was not seen at rest at the end of the run; check it before you go near it.</source>
        <translation>运行结束时未确认转台静止；靠近之前请先检查。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Run incomplete</source>
        <translation>运行未完成</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The run ended early; everything received is kept and analysed.</source>
        <translation>运行提前结束；已接收的全部数据均已保留并分析。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No delay</source>
        <translation>无延迟结果</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The run gave no delay.</source>
        <translation>本次运行未得到延迟结果。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Run failed</source>
        <translation>运行失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run failed: %1</source>
        <translation>运行失败：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;span style=&apos;color:#b00000&apos;&gt;Run failed: %1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b00000&apos;&gt;运行失败：%1&lt;/span&gt;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Re-analysing %1 …</source>
        <translation>正在重新分析 %1 …</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Opening %1 …</source>
        <translation>正在打开 %1 …</translation>
    </message>
    <message>
        <location line="+84"/>
        <location line="+10"/>
        <source>Re-analyse</source>
        <translation>重新分析</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Cannot re-analyse %1</source>
        <translation>无法重新分析 %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cannot open %1</source>
        <translation>无法打开 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1

File: %2</source>
        <translation>%1

文件：%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: re-analysed with the bench constants; the result was added to the session and is shown</source>
        <translation>%1：已用台架常数重新分析；结果已添加到会话并显示</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The session was analysed with the current bench constants and the result was added to it; its recorded data did not change. The Results view shows the new result; its Result list holds the earlier ones.

File: %1</source>
        <translation>已用当前台架常数分析该会话，结果已添加到会话中；其记录的数据未改变。“结果”视图显示新结果；其“结果”列表保留之前的结果。

文件：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: result %2 of %3 shown</source>
        <translation>%1：显示第 %2 个结果（共 %3 个）</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>run not recorded</source>
        <translation>未记录的运行</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1, result %2 of %3: %4</source>
        <translation>%1，结果 %2/%3：%4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 (not stored)</source>
        <translation>%1：%2（未保存）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 — fogbench %2</source>
        <translation>%1 — fogbench %2</translation>
    </message>
    <message>
        <location line="+149"/>
        <source>Compare %1</source>
        <translation>比较 %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the session could not be read (see the message)</source>
        <translation>无法读取该会话（见消息）</translation>
    </message>
    <message>
        <location line="-229"/>
        <source>%1 re-analysed</source>
        <translation>%1 已重新分析</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: read-only review</source>
        <translation>%1：只读查看</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Choose a session folder to import into first.</source>
        <translation>请先选择导入目标会话文件夹。</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+17"/>
        <source>Import CSV data</source>
        <translation>导入 CSV 数据</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>The imported data becomes a session file in the session folder; choose a folder you can write to in the Sessions view.</source>
        <translation>导入的数据将成为会话文件夹中的会话文件；请在“会话”视图中选择一个可写入的文件夹。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Importing %1 …</source>
        <translation>正在导入 %1 …</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot import %1</source>
        <translation>无法导入 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cannot import %1: %2</source>
        <translation>无法导入 %1：%2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Imported %1 as %2</source>
        <translation>已将 %1 导入为 %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>this run</source>
        <translation>本次运行</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Diagnosing %1 …</source>
        <translation>正在诊断 %1 …</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Diagnosis of %1 cancelled</source>
        <translation>%1 的诊断已取消</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No diagnosis: %1</source>
        <translation>无法诊断：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No diagnosis of %1</source>
        <translation>无法诊断 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No diagnosis of %1: %2</source>
        <translation>无法诊断 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Diagnosis of %1: %2 (%3 s)</source>
        <translation>%1 的诊断：%2（%3 s）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>This result has no static segment. To measure the gyro&apos;s noise (Allan deviation, noise terms, bias), add a test point of kind &quot;static&quot; to the plan: the table rests while the gyro is recorded.</source>
        <translation>此结果没有静态段。要测量陀螺噪声（Allan 方差、噪声项、零偏），请在计划中添加类型为“静态”的测试点：转台静止时记录陀螺数据。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Computing the Allan deviation …</source>
        <translation>正在计算 Allan 标准差 …</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>No noise analysis: %1</source>
        <translation>无噪声分析：%1</translation>
    </message>
</context>
<context>
    <name>fog::ui::NoiseView</name>
    <message>
        <location filename="../../ui/noise_view.cpp" line="+33"/>
        <source>Static segment</source>
        <translation>静态段</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Overlapping Allan deviation of the gyro</source>
        <translation>陀螺的重叠 Allan 标准差</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>noise term</source>
        <translation>噪声项</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>value</source>
        <translation>数值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>± 1σ</source>
        <translation>± 1σ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>from τ (s)</source>
        <translation>τ 范围 (s)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>No noise analysis yet.</source>
        <translation>尚无噪声分析。</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>%1: %2 gyro, %3 s</source>
        <translation>%1：%2 陀螺，%3 s</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&lt;b&gt;Test point %1, %2 gyro at rest for %3 s&lt;/b&gt; (%4 samples, %5 frames lost): bias %6 ± %7 °/h; Earth rate on this gyro %8 °/h; Earth-corrected bias &lt;b&gt;%9 °/h&lt;/b&gt;</source>
        <translation>&lt;b&gt;测试点 %1，%2 陀螺静止 %3 s&lt;/b&gt;（%4 个样本，丢失 %5 帧）：零偏 %6 ± %7 °/h；该陀螺上的地球自转分量 %8 °/h；扣除地球自转后的零偏 &lt;b&gt;%9 °/h&lt;/b&gt;</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&lt;br&gt;noise model: χ²/dof %1</source>
        <translation>&lt;br&gt;噪声模型：χ²/dof %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>averaging time τ (s)</source>
        <translation>平均时间 τ (s)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Allan deviation (°/h)</source>
        <translation>Allan 标准差 (°/h)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>confidence interval (%1 %)</source>
        <translation>置信区间（%1 %）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>measured</source>
        <translation>实测</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>noise model (sum)</source>
        <translation>噪声模型（合计）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>quantisation</source>
        <translation>量化噪声</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>angle random walk</source>
        <translation>角度随机游走</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>bias instability</source>
        <translation>零偏不稳定性</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rate random walk</source>
        <translation>角速率随机游走</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rate ramp</source>
        <translation>角速率斜坡</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Gauss–Markov bias</source>
        <translation>高斯-马尔可夫零偏</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
</context>
<context>
    <name>fog::ui::PlanEditor</name>
    <message>
        <location filename="../../ui/plan_editor.cpp" line="+82"/>
        <source>Preset</source>
        <translation>预设</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>custom plan</source>
        <translation>自定义计划</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choosing a preset replaces the plan below; an edited plan shows as &quot;custom plan&quot;</source>
        <translation>选择预设会替换下方的计划；编辑过的计划显示为“自定义计划”</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rest</source>
        <translation>静止</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+98"/>
        <location line="+2"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="-96"/>
        <source>Rest between test points: the table at rest</source>
        <translation>测试点之间的静止时间：转台静止</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Axis</source>
        <translation>轴</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Frequency</source>
        <translation>频率</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Amplitude</source>
        <translation>幅值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Duration</source>
        <translation>时长</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Periods</source>
        <translation>周期数</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Settle</source>
        <translation>稳定</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Check</source>
        <translation>检查</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Add test point</source>
        <translation>添加测试点</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove</source>
        <translation>删除</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move up</source>
        <translation>上移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move down</source>
        <translation>下移</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Replace the test plan?</source>
        <translation>替换测试计划？</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The plan below is not a preset (it was edited or loaded from a file). Replace it with the preset &quot;%1&quot;?</source>
        <translation>下方的计划不是预设（已被编辑或从文件载入）。要用预设“%1”替换它吗？</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>swing</source>
        <translation>摆动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>static</source>
        <translation>静态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>static: the table at rest, to measure the gyro&apos;s noise (Allan deviation)</source>
        <translation>静态：转台静止，用于测量陀螺噪声（Allan 方差）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>table position from the plan file: X %1°, Y %2°, Z %3°</source>
        <translation>计划文件中的转台位置：X %1°，Y %2°，Z %3°</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Swing frequency</source>
        <translation>摆动频率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Swing amplitude (peak)</source>
        <translation>摆动幅值（峰值）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recorded time after settling; or give whole periods in the next column</source>
        <translation>稳定后的记录时长；也可在下一列填写整周期数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recorded swing periods (duration × frequency)</source>
        <translation>记录的摆动周期数（时长 × 频率）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Swing time before recording starts</source>
        <translation>开始记录前的摆动时间</translation>
    </message>
    <message>
        <location line="+143"/>
        <source>1 problem</source>
        <translation>1 个问题</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 problems</source>
        <translation>%1 个问题</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ok</source>
        <translation>正常</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ok: table at rest, %1 in all</source>
        <translation>正常：转台静止，共 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ok: %1 periods, %2 in all</source>
        <translation>正常：%1 个周期，共 %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>test point %1: %2</source>
        <translation>测试点 %1：%2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the test plan has no test points: add one or load a preset</source>
        <translation>测试计划中没有测试点：请添加或载入预设</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 test point(s), %2 in all</source>
        <translation>%1 个测试点，共 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;span style=&apos;color:#b00000&apos;&gt;Cannot run: %1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b00000&apos;&gt;无法运行：%1&lt;/span&gt;</translation>
    </message>
</context>
<context>
    <name>fog::ui::PlotInteraction</name>
    <message>
        <location filename="../../ui/plots/plot_interaction.cpp" line="+148"/>
        <source>wheel: zoom time (Ctrl: both axes) · drag: pan · double-click: whole view</source>
        <translation>滚轮：缩放时间轴（Ctrl：两轴）· 拖动：平移 · 双击：全貌</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wheel: zoom · drag: pan · double-click: whole view</source>
        <translation>滚轮：缩放 · 拖动：平移 · 双击：全图</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> · click: cursors A/B · right-click: remove them</source>
        <translation> · 单击：光标 A/B · 右击：移除光标</translation>
    </message>
    <message>
        <location line="+113"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>B − A: Δt = %1</source>
        <translation>B − A：Δt = %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>B − A: Δ%1 = %2</source>
        <translation>B − A：Δ%1 = %2</translation>
    </message>
</context>
<context>
    <name>QAbstractFileIconProvider</name>
    <message>
        <location filename="../../ui/language/language.cpp" line="+49"/>
        <source>Folder</source>
        <comment>All other platforms</comment>
        <translation>文件夹</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../../ui/plots/delta_picker.cpp" line="-18"/>
        <source>%1 µs</source>
        <translation>%1 µs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../../ui/main_window.cpp" line="-1275"/>
        <location filename="../../ui/plan_editor.cpp" line="-321"/>
        <location filename="../../ui/plots/delta_picker.cpp" line="+1"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../../ui/live_view.cpp" line="-405"/>
        <source>%1:%2</source>
        <translation>%1:%2</translation>
    </message>
    <message>
        <location filename="../../ui/main_window.cpp" line="+0"/>
        <source>%1 min %2 s</source>
        <translation>%1 分 %2 秒</translation>
    </message>
    <message>
        <location filename="../../ui/plan_editor.cpp" line="+0"/>
        <source>%1 min</source>
        <translation>%1 分钟</translation>
    </message>
    <message>
        <location filename="../../ui/plots/plot_export.cpp" line="+13"/>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation>PNG 图像 (*.png);;SVG 矢量图 (*.svg);;PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <location filename="../../ui/report/calibration_report.cpp" line="+71"/>
        <location line="+271"/>
        <source>not recorded</source>
        <translation>未记录</translation>
    </message>
    <message>
        <location line="-264"/>
        <source>%1 axis
%2 Hz / %3°, %4 s</source>
        <translation>%1 轴
%2 Hz / %3°，%4 s</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 axis, %2 Hz / %3°, %4 s</source>
        <translation>%1 轴，%2 Hz / %3°，%4 s</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>IMU %1 · S/N %2</source>
        <translation>IMU %1 · 序列号 %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fogbench · IMU delay calibration report</source>
        <translation>fogbench · IMU 延迟标定报告</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Session %1 · raw data %2 · fogbench %3</source>
        <translation>会话 %1 · 原始数据 %2 · fogbench %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(date not recorded)</source>
        <translation>（未记录日期）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not hashed (imported)</source>
        <translation>未计算哈希（导入）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Page %1 of %2</source>
        <translation>第 %1 页，共 %2 页</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no raw stream (imported)</source>
        <translation>无原始数据流（导入）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 bytes of sampling-board stream</source>
        <translation>采样板数据流 %1 字节</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>— refused</source>
        <translation>— 被拒绝</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Test point %1 (%2): %3</source>
        <translation>测试点 %1（%2）：%3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>INVALID: no delay from %1</source>
        <translation>无效：%1 未给出延迟</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Tested by</source>
        <translation>测试人</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Reviewed and approved by</source>
        <translation>审核批准人</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Name, signature</source>
        <translation>姓名、签字</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Date</source>
        <translation>日期</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>IMU delay calibration report</source>
        <translation>IMU 延迟标定报告</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1, serial number %2</source>
        <translation>%1，序列号 %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Session</source>
        <translation>会话</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>IMU model</source>
        <translation>IMU 型号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU serial number</source>
        <translation>IMU 序列号</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recorded (UTC)</source>
        <translation>记录时间 (UTC)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data source</source>
        <translation>数据来源</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recorded with</source>
        <translation>记录软件</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Report produced</source>
        <translation>报告生成</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 by fogbench %2</source>
        <translation>%1，由 fogbench %2 生成</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Raw data</source>
        <translation>原始数据</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Raw data SHA-256</source>
        <translation>原始数据 SHA-256</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>none: no raw stream (imported)</source>
        <translation>无：无原始数据流（导入）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Notes</source>
        <translation>备注</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Results</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>condition</source>
        <translation>条件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lag ± 1σ (ms)</source>
        <translation>滞后 ± 1σ (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CRLB (ms)</source>
        <translation>CRLB (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU delay ± 1σ (ms)</source>
        <translation>IMU 延迟 ± 1σ (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro delay ± 1σ (ms)</source>
        <translation>陀螺延迟 ± 1σ (ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>verdict</source>
        <translation>结论</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>No delay from %1</source>
        <translation>%1 未得到延迟</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Delay against frequency, %1 axis (%2 frequencies): weighted lag %3 ms, χ² %4 on %5 dof, p = %6: %7.</source>
        <translation>延迟随频率变化，%1 轴（%2 个频率）：加权滞后 %3 ms，χ² = %4，自由度 %5，p = %6：%7。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>consistent with a pure delay</source>
        <translation>与纯延迟一致</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NOT a pure delay (frequency-dependent)</source>
        <translation>不是纯延迟（随频率变化）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Sign-off</source>
        <translation>签署</translation>
    </message>
    <message>
        <location line="+128"/>
        <source>Bench constants</source>
        <translation>测试台常数</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+242"/>
        <source>quantity</source>
        <translation>量</translation>
    </message>
    <message>
        <location line="-241"/>
        <location line="+334"/>
        <source>value</source>
        <translation>数值</translation>
    </message>
    <message>
        <location line="-333"/>
        <source>std. uncertainty</source>
        <translation>标准不确定度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>role</source>
        <translation>作用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 (taken as exact)</source>
        <translation>0（视为精确）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>table read delay</source>
        <translation>转台读数延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>added to the lag: IMU delay</source>
        <translation>加到滞后上：IMU 延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>processing-board delay</source>
        <translation>处理板延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subtracted from the IMU delay: gyro delay</source>
        <translation>从 IMU 延迟中扣除：陀螺延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro pulse equivalent</source>
        <translation>陀螺脉冲当量</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1″/pulse</source>
        <translation>%1″/脉冲</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sampling-board counter</source>
        <translation>采样板计数器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 MHz, %2 bit</source>
        <translation>%1 MHz，%2 位</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>imported: times in seconds on the other bench&apos;s common clock</source>
        <translation>导入数据：时间为另一台架公共时钟上的秒数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>common time base of both channels</source>
        <translation>两通道的公共时间基准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>latitude</source>
        <translation>纬度</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Earth rate, absorbed by the fitted gyro trend</source>
        <translation>地球自转角速率，由拟合的陀螺趋势项吸收</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Test plan</source>
        <translation>测试计划</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+18"/>
        <source>axis</source>
        <translation>轴</translation>
    </message>
    <message>
        <location line="-17"/>
        <location line="+344"/>
        <source>frequency (Hz)</source>
        <translation>频率 (Hz)</translation>
    </message>
    <message>
        <location line="-343"/>
        <source>amplitude (°)</source>
        <translation>幅值 (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>duration (s)</source>
        <translation>时长 (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>settle (s)</source>
        <translation>稳定 (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>start phase (°)</source>
        <translation>起始相位 (°)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Table at rest for %1 s between test points.</source>
        <translation>测试点之间转台静止 %1 s。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>nominal frequency (Hz)</source>
        <translation>标称频率 (Hz)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nominal amplitude (°)</source>
        <translation>标称幅值 (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recorded (s)</source>
        <translation>记录时长 (s)</translation>
    </message>
    <message>
        <location line="-38"/>
        <location line="+41"/>
        <source>not stated</source>
        <translation>未给出</translation>
    </message>
    <message>
        <location line="-393"/>
        <source>SIMULATED DATA — not a measurement of a real IMU</source>
        <translation>仿真数据 —— 并非对真实 IMU 的测量</translation>
    </message>
    <message>
        <location line="+150"/>
        <source>Result reported</source>
        <translation>报告的结果</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>computed when this report was produced, with the constants on page 2</source>
        <translation>生成本报告时计算，使用第 2 页的常数</translation>
    </message>
    <message>
        <location line="+45"/>
        <source> %1 refused test point(s) left out: their checks failed.</source>
        <translation>未计入 %1 个被拒绝的测试点：其有效性检查未通过。</translation>
    </message>
    <message>
        <location line="+153"/>
        <source>the stream&apos;s statement, else the bench constant: turns pulses into degrees</source>
        <translation>数据流给出的值，否则为测试台常数：把脉冲换算为度</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>IMU frame</source>
        <translation>IMU 坐标系</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the IMU&apos;s axes at zero table angles; the diagnosis checks it against the data</source>
        <translation>转台各轴为零时 IMU 各轴的指向；诊断用数据检验它</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>The plan was not recorded with the data; the test points as the stream states them:</source>
        <translation>数据未附带测试计划；以下为数据流给出的测试点：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Data integrity</source>
        <translation>数据完整性</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>table frames</source>
        <translation>转台帧</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>checksum failures</source>
        <translation>校验失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU frames</source>
        <translation>IMU 帧</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>lost frames</source>
        <translation>丢失帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>status frames</source>
        <translation>状态帧</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>duplicate / out-of-order frames</source>
        <translation>重复 / 乱序帧</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>counter wraps</source>
        <translation>计数器回绕</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>bytes skipped</source>
        <translation>跳过字节</translation>
    </message>
    <message>
        <location line="-190"/>
        <source>Delay budget</source>
        <translation>延迟预算</translation>
    </message>
    <message>
        <location line="-182"/>
        <source>Decision rule (ISO/IEC 17025:2017 §7.8.6; ILAC-G8:09/2019 guarded acceptance, one-sided): a test point is invalid when a validity check fails (reversed gyro axis, clock-rate mismatch, a swing that is not a steady sinusoid, a negative IMU delay); otherwise it passes when its IMU delay plus k = %1 standard uncertainties (1σ, including the bench constants; guard band kσ) is below the limit of %2 ms, and fails if not; the session passes when every test point of the plan gave a delay and passes. Maximum probability of false accept 1 − Φ(k) = %3: a delay measured just at the acceptance boundary, with a Gaussian error of the stated σ.</source>
        <translation>判定规则（ISO/IEC 17025:2017 §7.8.6；ILAC-G8:09/2019 保护带验收，单侧）：有效性检查未通过（陀螺轴反向、时钟速率不一致、摆动不是稳定正弦、IMU 延迟为负）的测试点无效；否则，其 IMU 延迟加 k = %1 倍标准不确定度（1σ，含台架常数；保护带 kσ）低于 %2 ms 限值时合格，否则不合格；计划中每个测试点都得到延迟且都合格时，会话合格。最大误接受概率 1 − Φ(k) = %3：即恰好在验收边界上测得的延迟（误差为所给 σ 的高斯分布）。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>k %1.</source>
        <translation>k %1。</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>Lot</source>
        <translation>批次</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bench id</source>
        <translation>工位编号</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>P(false accept)</source>
        <translation>P(误接受)</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Lag: gyro output behind the stamped table angle (joint fit). IMU delay = lag + table read delay; gyro delay = IMU delay − processing-board delay. CRLB: Cramér–Rao bound on the lag for the noise measured in this session. P(false accept): the probability that the true IMU delay is at or above the limit, 1 − Φ((limit − delay)/σ), for a Gaussian error of the stated σ; none for a refused (INVALID or INCOMPLETE) delay.</source>
        <translation>滞后：陀螺输出相对于打时间戳的转台角度的滞后（联合拟合）。IMU 延迟 = 滞后 + 转台读数延迟；陀螺延迟 = IMU 延迟 − 处理板延迟。CRLB：按本次会话实测噪声计算的滞后 Cramér–Rao 界。P(误接受)：真实 IMU 延迟达到或超过限值的概率 1 − Φ((限值 − 延迟)/σ)（误差为所给 σ 的高斯分布）；被拒绝（无效或不完整）的延迟不给出。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Not shown: the paper&apos;s theoretical budget describes its own gyro and processing board, and this recording was made on another bench (imported).</source>
        <translation>未显示：论文的理论预算描述的是其自身的陀螺和处理板，而本记录来自另一台架（导入）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Delay budget: the paper&apos;s theory beside the measurement</source>
        <translation>延迟预算：论文理论值与测量值对照</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+197"/>
        <source>#%1: %2</source>
        <translation>#%1：%2</translation>
    </message>
    <message>
        <location line="-196"/>
        <source>#%1: refused (%2, %3)</source>
        <translation>#%1：被拒绝（%2，%3）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>stage</source>
        <translation>环节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>theory (ms)</source>
        <translation>理论值 (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+335"/>
        <source>basis</source>
        <translation>依据</translation>
    </message>
    <message>
        <location line="-334"/>
        <source>measured (ms)</source>
        <translation>测量值 (ms)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>gyro&apos;s own delay</source>
        <translation>陀螺自身延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sensing, loop and pulse update</source>
        <translation>敏感、闭环与脉冲更新</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>processing board</source>
        <translation>处理板</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sampling, compensation, serial</source>
        <translation>采样、补偿、串口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (bench constant)</source>
        <translation>%1（测试台常数）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU delay (total)</source>
        <translation>IMU 延迟（总计）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the paper: &lt; 0.8 ms</source>
        <translation>论文：&lt; 0.8 ms</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Theory with the paper&apos;s figures: %1 m of fibre (eigen period %2 µs), loop delay ≤ %3 eigen periods, pulse output updated every %4 ms, %5 MHz board clock, %6-byte frames at %7 Mbaud.</source>
        <translation>按论文参数的理论值：光纤 %1 m（本征周期 %2 µs），回路延迟 ≤ %3 个本征周期，脉冲输出每 %4 ms 更新，处理板时钟 %5 MHz，%6 字节帧、%7 Mbaud。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>(no time)</source>
        <translation>（无时间）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>#%1 %2 · cannot be read: %3</source>
        <translation>#%1 %2 · 无法读取：%3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>login name</source>
        <translation>登录名</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>recording run</source>
        <translation>记录运行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command-line analysis</source>
        <translation>命令行分析</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GUI Results view</source>
        <translation>图形界面“结果”视图</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>by %1 (%2) · %3</source>
        <translation>分析者 %1（%2）· %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>who and with what: not recorded (stored before the audit trail)</source>
        <translation>分析者与工具：未记录（保存于审计记录之前）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>table read delay %1 ± %2 ms, board delay %3 ± %4 ms, limit %5 ms</source>
        <translation>转台读数延迟 %1 ± %2 ms，处理板延迟 %3 ± %4 ms，限值 %5 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>gyro signs %1</source>
        <translation>陀螺符号 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>version not recorded</source>
        <translation>版本未记录</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>raw data not recorded</source>
        <translation>原始数据未记录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw data hash not known</source>
        <translation>原始数据哈希未知</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>#%1 %2 %3 · %4 · %5 · %6 · %7</source>
        <translation>#%1 %2 %3 · %4 · %5 · %6 · %7</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>gyro signs</source>
        <translation>陀螺符号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>−1: the gyro axis counts against the table&apos;s; its increments are negated</source>
        <translation>−1：陀螺轴与转台轴反向计数；其增量取反</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Analyses of this session</source>
        <translation>本会话的分析记录</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Each line: number, when stored (UTC), who (operator named, or login), tool and command, constants, software version, SHA-256 of the raw data analysed (first 12 digits), verdict as stored.</source>
        <translation>每行：序号、保存时间（UTC）、分析者（所填操作员或登录名）、工具与命令、常数、软件版本、所分析原始数据的 SHA-256（前 12 位）、所保存的判定。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>test point</source>
        <translation>测试点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>paper&apos;s resolution, 0.5 °/h (µs)</source>
        <translation>论文分辨率，0.5 °/h (µs)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cramér–Rao bound (µs)</source>
        <translation>Cramér–Rao 界 (µs)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lag std. error (µs)</source>
        <translation>滞后标准误差 (µs)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The paper&apos;s resolution figure is the gyro&apos;s angle error over one period divided by the peak rate; the bench&apos;s own uncertainty is the joint fit&apos;s standard error, checked against the Cramér–Rao bound for the noise measured in this session.</source>
        <translation>论文的分辨率指标为陀螺在一个周期内的角度误差除以峰值角速率；本测试台自身的不确定度为联合拟合的标准误差，并以本次会话实测噪声的 Cramér–Rao 界加以核对。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Test point %1: %2 — angles and fits</source>
        <translation>测试点 %1：%2 —— 角度及拟合</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Angles: the middle three periods (%1 s to %2 s on the board&apos;s time axis), offset removed; the gyro angle is the sum of its increments with the fitted trend (bias + Earth rate) removed. Fits: the 4-parameter fits of the table below. Residuals: the whole record (%3 s), data minus fit; the table&apos;s are its encoder quantisation, the gyro&apos;s its angle random walk and pulse quantisation.</source>
        <translation>角度：中间三个周期（采样板时间轴上 %1 s 至 %2 s），已去除偏置；陀螺角度为其增量之和，并去除了拟合的趋势项（零偏 + 地球自转）。拟合：下表中的四参数拟合。残差：整段记录（%3 s），数据减拟合；转台残差为编码器量化，陀螺残差为角度随机游走和脉冲量化。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Table angle (offset removed) and fit</source>
        <translation>转台角度（已去除偏置）及拟合</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+16"/>
        <location line="+16"/>
        <location line="+12"/>
        <location line="+93"/>
        <source>time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <location line="-136"/>
        <location line="+16"/>
        <source>angle (°)</source>
        <translation>角度 (°)</translation>
    </message>
    <message>
        <location line="-9"/>
        <location line="+16"/>
        <source>fit: A = %1°, T = %2 ms</source>
        <translation>拟合：A = %1°，T = %2 ms</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Gyro angle (offset and trend removed) and fit</source>
        <translation>陀螺角度（已去除偏置和趋势）及拟合</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Table residuals</source>
        <translation>转台残差</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>table − fit (arcsec)</source>
        <translation>转台 − 拟合（角秒）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>table angle − fit, RMS %1″</source>
        <translation>转台角度 − 拟合，RMS %1″</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Gyro residuals (cumulative angle)</source>
        <translation>陀螺残差（累积角度）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>gyro − fit (arcsec)</source>
        <translation>陀螺 − 拟合（角秒）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>gyro angle − fit, RMS %1″</source>
        <translation>陀螺角度 − 拟合，RMS %1″</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>nominal</source>
        <translation>标称</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Test point %1: %2 — fits and delay</source>
        <translation>测试点 %1：%2 —— 拟合与延迟</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>fit</source>
        <translation>拟合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>period T (ms)</source>
        <translation>周期 T (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>σ(T) (µs)</source>
        <translation>σ(T) (µs)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>phase t₀ (ms)</source>
        <translation>相位 t₀ (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>σ(t₀) (µs)</source>
        <translation>σ(t₀) (µs)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>amplitude A (°)</source>
        <translation>幅值 A (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>σ(A) (″)</source>
        <translation>σ(A) (″)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+205"/>
        <source>χ²/dof</source>
        <translation>χ²/dof</translation>
    </message>
    <message>
        <location line="-204"/>
        <source>table, 3-parameter</source>
        <translation>转台，三参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro, 3-parameter</source>
        <translation>陀螺，三参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table, 4-parameter</source>
        <translation>转台，四参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro, 4-parameter</source>
        <translation>陀螺，四参数</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>joint: lag as t₀</source>
        <translation>联合：以滞后为 t₀</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>angle = A sin(2π (t − t₀)/T) + offset (gyro: + trend·t), t₀ wrapped into (−T/2, T/2]; σ: standard uncertainties (1σ). 3-parameter fits at the nominal frequency (a χ²/dof far above 1 says the table&apos;s frequency is off nominal), 4-parameter fits with the frequency free, and the joint fit: one frequency for both channels and the lag (gyro t₀ − table t₀) as a parameter; its gyro/table amplitude ratio is %1 ± %2.</source>
        <translation>角度 = A sin(2π (t − t₀)/T) + 偏置（陀螺：+ 趋势·t），t₀ 折算到 (−T/2, T/2]；σ：标准不确定度（1σ）。三参数拟合采用标称频率（χ²/dof 远大于 1 说明转台频率偏离标称值），四参数拟合频率自由，联合拟合两通道共用一个频率并以滞后（陀螺 t₀ − 转台 t₀）为参数；其陀螺/转台幅值比为 %1 ± %2。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>value (ms)</source>
        <translation>数值 (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1σ (ms)</source>
        <translation>1σ (ms)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>measured lag (gyro behind table)</source>
        <translation>测得滞后（陀螺落后于转台）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>joint fit; CRLB %1 ms, σ/CRLB %2</source>
        <translation>联合拟合；CRLB %1 ms，σ/CRLB %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> — σ below the bound: understated (check uncertainty_below_bound)</source>
        <translation> — σ 低于克拉美–罗界：不确定度被低估（检查 uncertainty_below_bound）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>+ table read delay</source>
        <translation>+ 转台读数延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+4"/>
        <source>bench constant</source>
        <translation>测试台常数</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>= IMU delay</source>
        <translation>= IMU 延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>limit %1 ms: %2</source>
        <translation>限值 %1 ms：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>− processing-board delay</source>
        <translation>− 处理板延迟</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>= gyro&apos;s own delay</source>
        <translation>= 陀螺自身延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per-period lag, mean and scatter</source>
        <translation>逐周期滞后的均值与离散度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 whole periods, 3-parameter fits</source>
        <translation>%1 个整周期，三参数拟合</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Delay</source>
        <translation>延迟</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Guard band kσ = %1 ms (k = %2); probability that the true IMU delay is at or above the limit: %3.</source>
        <translation>保护带 kσ = %1 ms（k = %2）；真实 IMU 延迟达到或超过限值的概率：%3。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No false-accept probability: the delay is refused (%1).</source>
        <translation>不给出误接受概率：该延迟被拒绝（%1）。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Lag per swing period</source>
        <translation>各摆动周期的滞后</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+108"/>
        <source>lag (ms)</source>
        <translation>滞后 (ms)</translation>
    </message>
    <message>
        <location line="-98"/>
        <source>one period</source>
        <translation>单个周期</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>joint fit, %1 ms</source>
        <translation>联合拟合，%1 ms</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Noise and fit quality</source>
        <translation>噪声与拟合质量</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>encoder noise</source>
        <translation>编码器噪声</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <source>%1″ (1σ)</source>
        <translation>%1″（1σ）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>gyro pulse quantisation</source>
        <translation>陀螺脉冲量化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro angle random walk</source>
        <translation>陀螺角度随机游走</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 °/√h</source>
        <translation>%1 °/√h</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro trend</source>
        <translation>陀螺趋势</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 °/h (bias + Earth rate)</source>
        <translation>%1 °/h（零偏 + 地球自转）</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+47"/>
        <source>samples</source>
        <translation>样本</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>%1 table, %2 IMU, %3 IMU frames lost</source>
        <translation>转台 %1，IMU %2，丢失 IMU 帧 %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Test point %1: %2 gyro at rest for %3 s — noise</source>
        <translation>测试点 %1：%2 陀螺静止 %3 s —— 噪声</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Overlapping Allan deviation of the gyro</source>
        <translation>陀螺的重叠 Allan 标准差</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>averaging time τ (s)</source>
        <translation>平均时间 τ (s)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Allan deviation (°/h)</source>
        <translation>Allan 标准差 (°/h)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confidence interval (%1 %)</source>
        <translation>置信区间（%1 %）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>measured</source>
        <translation>实测</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>noise model (sum)</source>
        <translation>噪声模型（合计）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>quantisation</source>
        <translation>量化噪声</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>angle random walk</source>
        <translation>角度随机游走</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>bias instability</source>
        <translation>零偏不稳定性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rate random walk</source>
        <translation>角速率随机游走</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rate ramp</source>
        <translation>角速率斜坡</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Gauss–Markov bias</source>
        <translation>高斯-马尔可夫零偏</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>noise term</source>
        <translation>噪声项</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>± 1σ</source>
        <translation>± 1σ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>from τ (s)</source>
        <translation>τ 范围 (s)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Noise terms (IEEE Std 952)</source>
        <translation>噪声项（IEEE Std 952）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bias</source>
        <translation>零偏</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 ± %2 °/h</source>
        <translation>%1 ± %2 °/h</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Earth rate on this gyro</source>
        <translation>该陀螺上的地球自转分量</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <source>%1 °/h</source>
        <translation>%1 °/h</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Earth-corrected bias</source>
        <translation>扣除地球自转后的零偏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 every %2 ms, %3 frames lost</source>
        <translation>%1 个，每 %2 ms，丢失 %3 帧</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>model fit</source>
        <translation>模型拟合</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>χ²/dof %1</source>
        <translation>χ²/dof %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Frequency response, %1 axis: gyro angle / table angle at %2 frequencies</source>
        <translation>频率响应，%1 轴：%2 个频率下的陀螺角度 / 转台角度</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>measured ±1σ</source>
        <translation>测量值 ±1σ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Magnitude</source>
        <translation>幅值</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+13"/>
        <source>|H| (dB)</source>
        <translation>|H|（dB）</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Phase (negative: the gyro lags)</source>
        <translation>相位（负值：陀螺滞后）</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+13"/>
        <source>phase (°)</source>
        <translation>相位（°）</translation>
    </message>
    <message>
        <location line="-3"/>
        <location line="+19"/>
        <source>point</source>
        <translation>点</translation>
    </message>
    <message>
        <location line="-19"/>
        <location line="+20"/>
        <source>f (Hz)</source>
        <translation>f（Hz）</translation>
    </message>
    <message>
        <location line="-19"/>
        <source>|H|</source>
        <translation>|H|</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>σ</source>
        <translation>σ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>σ (dB)</source>
        <translation>σ（dB）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>σ (°)</source>
        <translation>σ（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>σ (ms)</source>
        <translation>σ（ms）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Complex gain of each test point that passed its checks, from its joint fit: magnitude gyro/table amplitude, phase −2π f · lag; standard uncertainties (1σ).</source>
        <translation>每个通过检查的测试点的复增益，来自其联合拟合：幅值为陀螺/转台振幅之比，相位为 −2π f · 滞后；标准不确定度（1σ）。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>phase vs motion (°)</source>
        <translation>相对转台运动的相位 (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>u, fit (°)</source>
        <translation>u，拟合 (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>u, read delay (°)</source>
        <translation>u，读数延迟 (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>U (k = 2), °</source>
        <translation>U (k = 2)，°</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>U (k = 2), ms</source>
        <translation>U (k = 2)，ms</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Models fitted to all points (weighted least squares on magnitude and phase)</source>
        <translation>对所有点拟合的模型（幅值与相位的加权最小二乘）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>model</source>
        <translation>模型</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>p (fit)</source>
        <translation>p（拟合）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>AIC</source>
        <translation>AIC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>BIC</source>
        <translation>BIC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>parameters (± 1σ)</source>
        <translation>参数（± 1σ）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Model left out: %1</source>
        <translation>未拟合的模型：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>p (fit): the probability of a χ² this large were the model true. A model is chosen only when its fit is adequate (p ≥ %1) and its parameters are physical (docs/method.md).</source>
        <translation>p（拟合）：若模型成立，χ² 不小于此值的概率。仅当模型拟合充分（p ≥ %1）且参数符合物理时才被选中（docs/method.md）。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is not admissible: %2</source>
        <translation>%1 不可接受：%2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No model fits: the measured points alone are the response. %1</source>
        <translation>没有模型拟合：响应仅由测量点给出。%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>low-frequency delay</source>
        <translation>低频延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+2"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>group delay at %1 Hz</source>
        <translation>%1 Hz 处群延迟</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>−3 dB bandwidth</source>
        <translation>−3 dB 带宽</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none: a pure delay keeps its magnitude</source>
        <translation>无：纯延迟不改变幅值</translation>
    </message>
    <message>
        <location filename="../../ui/verdict_text.cpp" line="+21"/>
        <source>NO VERDICT</source>
        <translation>无判定</translation>
    </message>
    <message>
        <location filename="../../ui/report/calibration_report.cpp" line="+153"/>
        <source>%1 of %2 test points failed a validity check</source>
        <translation>%2 个测试点中有 %1 个未通过有效性检查</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no test point gave a delay</source>
        <translation>没有测试点给出延迟</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>INVALID: the result cannot be vouched for: %1.</source>
        <translation>无效：结果无法保证：%1。</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>FAIL against the %1 ms limit: %2 of %3 test points exceed the limit.</source>
        <translation>对 %1 ms 限值不合格：%3 个测试点中有 %2 个超限。</translation>
    </message>
    <message>
        <location line="-192"/>
        <source>The phase against the table&apos;s motion: the phase above less 2π f · d (d = %1 ms, the table read delay); its expanded uncertainty U = k·√(u_f² + u_d²) with k = 2, u_f the fit&apos;s and u_d = 2π f · %2 ms (the read delay&apos;s standard uncertainty).</source>
        <translation>相对转台运动的相位：上表相位减去 2π f · d（d = %1 ms，转台读数延迟）；其扩展不确定度 U = k·√(u_f² + u_d²)，k = 2，u_f 为拟合分量，u_d = 2π f · %2 ms（读数延迟的标准不确定度）。</translation>
    </message>
    <message>
        <location line="+187"/>
        <source>PASS: every test point passed its validity checks and its IMU delay + %1σ is below the %2 ms limit.</source>
        <translation>合格：每个测试点都通过有效性检查，且其 IMU 延迟 + %1σ 低于 %2 ms 限值。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 test point(s) gave no delay</source>
        <translation>%1 个测试点未得到延迟</translation>
    </message>
    <message>
        <location line="-469"/>
        <source>table angle (encoder, %1 ms)</source>
        <translation>转台角度（编码器，%1 ms）</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>gyro angle (summed increments, %1 ms)</source>
        <translation>陀螺角度（增量累加，%1 ms）</translation>
    </message>
    <message>
        <location line="+430"/>
        <source>INCOMPLETE (the run stopped early); its data give %1</source>
        <translation>不完整（运行提前停止）；其数据给出 %1</translation>
    </message>
    <message>
        <location filename="../../ui/verdict_text.cpp" line="-3"/>
        <source>INCOMPLETE</source>
        <translation>不完整</translation>
    </message>
    <message>
        <location filename="../../ui/report/calibration_report.cpp" line="-223"/>
        <source>model (chosen)</source>
        <translation>模型（所选）</translation>
    </message>
    <message>
        <location line="+85"/>
        <source>chosen (lowest AIC; a filter at 3σ)</source>
        <translation>所选（AIC 最低；滤波器须达 3σ）</translation>
    </message>
    <message>
        <location filename="../../ui/verdict_text.cpp" line="-3"/>
        <source>PASS</source>
        <translation>通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FAIL</source>
        <translation>不通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>INVALID</source>
        <translation>无效</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>INVALID: %1</source>
        <translation>无效：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>a validity check failed</source>
        <translation>一项有效性检查未通过</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>INCOMPLETE: the run stopped before its plan ended (its data give %1)</source>
        <translation>不完整：运行在计划结束前停止（其数据给出 %1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NO VERDICT: %1</source>
        <translation>无判定：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the stored result states none for this test point</source>
        <translation>已保存的结果未给出此测试点的判定</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>refused (%1)</source>
        <translation>被拒绝（%1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refused (%1, %2)</source>
        <translation>被拒绝（%1，%2）</translation>
    </message>
    <message>
        <location filename="../../ui/report/calibration_report.cpp" line="+169"/>
        <source>INCOMPLETE: the run stopped before its plan ended (%1); no calibration verdict. The data recorded give %2.</source>
        <translation>不完整：运行在计划结束前停止（%1）；没有校准判定。已记录的数据给出 %2。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>NO VERDICT: the stored result states none; re-analyse the session to store one.</source>
        <translation>无判定：已保存的结果未给出判定；请重新分析会话以保存判定。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>This version&apos;s analysis of the same data with the stored settings differs from the stored result (%1); the verdict is the stored one.</source>
        <translation>本版本用已保存的设置对同一数据的分析与已保存结果不同（%1）；判定以已保存的为准。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>IMU delay calibration report: %1 %2</source>
        <translation>IMU 延迟标定报告：%1 %2</translation>
    </message>
    <message>
        <location filename="../../ui/result_view.cpp" line="+71"/>
        <source>%1: %2 axis, %3 Hz / %4°</source>
        <translation>%1：%2 轴，%3 Hz / %4°</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>table read %1 ms, board %2 ms</source>
        <translation>转台读数 %1 ms，处理板 %2 ms</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>rates as frame averages (%1 ms frames)</source>
        <translation>角速率为帧平均（帧长 %1 ms）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rates sampled at their stamps</source>
        <translation>角速率在时标处采样</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cut at the swing windows %1</source>
        <translation>按摆动时间窗 %1 切分</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, imported with %1</source>
        <translation>，导入设置：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>; </source>
        <translation>；</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>, gyro signs %1, IMU frame %2</source>
        <translation>，陀螺符号 %1，IMU 坐标系 %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>, limit %1 ms</source>
        <translation>，限值 %1 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, k = %1</source>
        <translation>，k = %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, k = 2 (not stored: the rule of that version)</source>
        <translation>，k = 2（未保存：该版本的规则）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>version not stated</source>
        <translation>未注明版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fogbench %1</source>
        <translation>fogbench %1</translation>
    </message>
    <message>
        <location filename="../../ui/session_compare.cpp" line="+21"/>
        <source>%1 axis, %2 Hz / %3°</source>
        <translation>%1 轴，%2 Hz / %3°</translation>
    </message>
    <message>
        <location filename="../../ui/session_browser.cpp" line="+36"/>
        <source>; %1 damaged</source>
        <translation>；%1 个损坏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>damaged (%1 of %2)</source>
        <translation>损坏（%2 个中的 %1 个）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2 of %3%4)</source>
        <translation>%1（%3 个中的第 %2 个%4）</translation>
    </message>
    <message>
        <location filename="../../ui/data_export.cpp" line="+177"/>
        <source>Cannot create %1: %2. Nothing was written; choose another folder.</source>
        <translation>无法创建 %1：%2。未写入任何内容；请选择其他文件夹。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Could not write all of %1 (%2; disk full?). Nothing was changed there; free some space or choose another folder.</source>
        <translation>未能完整写入 %1（%2；磁盘已满？）。该处未作任何改动；请释放空间或选择其他文件夹。</translation>
    </message>
</context>
<context>
    <name>fog::ui::ResultView</name>
    <message>
        <location filename="../../ui/result_view.cpp" line="+52"/>
        <source>Test point</source>
        <translation>测试点</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Diagnose</source>
        <translation>诊断</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Compare with the simulator replaying this session: where the gap lies and which unmodelled effect explains it</source>
        <translation>与回放本会话的仿真器比较：差异在哪里，由哪种未建模效应解释</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The session keeps every analysis of it (the recording&apos;s, each re-analysis) with the constants and software version that made it; the chosen one is shown, reported and exported</source>
        <translation>会话保存对它的每次分析（记录时的、每次重新分析的）及其所用常数和软件版本；所选的一个用于显示、报告和导出</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Normalised angles and fits</source>
        <translation>归一化角度及拟合</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>(angle − offset) / amplitude</source>
        <translation>（角度 − 偏置）/ 幅值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Residuals (data − fit)</source>
        <translation>残差（数据 − 拟合）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>residual (arcsec)</source>
        <translation>残差（角秒）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>″</source>
        <translation>″</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No result yet.
Run a test plan (Run), or open a session (Sessions).</source>
        <translation>尚无结果。
请运行测试计划（运行），或打开会话（会话）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The fits&apos; residuals appear here.</source>
        <translation>拟合残差将显示在此处。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>fit</source>
        <translation>拟合</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>period (ms)</source>
        <translation>周期 (ms)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>σ (µs)</source>
        <translation>σ (µs)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>phase t₀ (ms)</source>
        <translation>相位 t₀ (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>amplitude (°)</source>
        <translation>幅值 (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>χ²/dof</source>
        <translation>χ²/dof</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>delay</source>
        <translation>延迟</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>value (ms)</source>
        <translation>数值 (ms)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>1σ (ms)</source>
        <translation>1σ (ms)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>theory (ms)</source>
        <translation>理论值 (ms)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>basis</source>
        <translation>依据</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Zero crossing: the gyro behind the table</source>
        <translation>过零点：陀螺滞后于转台</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>angle − offset (°)</source>
        <translation>角度 − 偏置 (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>time from the table fit&apos;s zero crossing (ms)</source>
        <translation>距转台拟合过零点的时间 (ms)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Zero crossing</source>
        <translation>过零点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lag vs frequency</source>
        <translation>滞后与频率</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Table and gyro angle around a zero crossing with the fitted lag marked: click twice to set cursors A and B and read Δt</source>
        <translation>过零点附近的转台角与陀螺角，标出拟合滞后：单击两次设置光标 A 和 B，读出 Δt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The lag of every test point against its swing frequency</source>
        <translation>各测试点的滞后随摆动频率的变化</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>The delay report appears here after a run.</source>
        <translation>运行结束后，延迟报告显示在这里。</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+4"/>
        <source>Export plot</source>
        <translation>导出曲线</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Angles plot…</source>
        <translation>角度曲线…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Residuals plot…</source>
        <translation>残差曲线…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zero crossing plot…</source>
        <translation>过零点图…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delay vs frequency plot…</source>
        <translation>延迟-频率曲线…</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Calibration report (PDF)…</source>
        <translation>标定报告（PDF）…</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+5"/>
        <source>Calibration report</source>
        <translation>标定报告</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>No result yet: run a test plan (Run) or open a session (Sessions).</source>
        <translation>尚无结果：请运行测试计划（运行）或打开会话（会话）。</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>result %1 of %2: %7, stored %3 by %4 (%5), %6</source>
        <translation>结果 %1/%2：%7，%3 由 %4（%5）保存，%6</translation>
    </message>
    <message>
        <location line="-136"/>
        <source>PDF document (*.pdf)</source>
        <translation>PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <location line="-89"/>
        <source>Fit table</source>
        <translation>拟合表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The 3- and 4-parameter fits of table and gyro and the joint fit: period, phase, amplitude, χ²/dof</source>
        <translation>转台与陀螺的三参数、四参数拟合及联合拟合：周期、相位、幅值、χ²/dof</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Fits</source>
        <translation>拟合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency response</source>
        <translation>频率响应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Report</source>
        <translation>报告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The chosen test point&apos;s angles with their fitted sinusoids, and the residuals</source>
        <translation>所选测试点的角度及其拟合正弦曲线，以及残差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnitude and phase of gyro angle / table angle at every test frequency of an axis, with the delay models fitted to them (Bode plot)</source>
        <translation>某轴各测试频率下陀螺角度 / 转台角度的幅值与相位，及对其拟合的延迟模型（伯德图）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The delay report as text, as the command line prints it</source>
        <translation>文本形式的延迟报告，与命令行输出一致</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Bode plot (frequency response)…</source>
        <translation>伯德图（频率响应）…</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+3"/>
        <source>Export the Bode plot</source>
        <translation>导出伯德图</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Delay table (CSV)…</source>
        <translation>延迟表（CSV）…</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+3"/>
        <source>Delay table (CSV)</source>
        <translation>延迟表（CSV）</translation>
    </message>
    <message>
        <location line="-2"/>
        <location line="+7"/>
        <source>CSV file (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>Frequency response: points and models (CSV)…</source>
        <translation>频率响应：测试点与模型 (CSV)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Frequency response (CSV): the points; the models go beside them</source>
        <translation>频率响应 (CSV)：测试点；模型写在其旁</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Frequency response (CSV)</source>
        <translation>频率响应 (CSV)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Session data and fits (CSV folder)…</source>
        <translation>会话数据与拟合（CSV 文件夹）…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Session data: name a new folder</source>
        <translation>会话数据：为新文件夹命名</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Session data (CSV)</source>
        <translation>会话数据（CSV）</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+10"/>
        <source>%1
The session itself is unchanged.</source>
        <translation>%1
会话本身未被改动。</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>Session data and result (HDF5 file)…</source>
        <translation>会话数据与结果（HDF5 文件）…</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+4"/>
        <source>Session data (HDF5)</source>
        <translation>会话数据（HDF5）</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>HDF5 file (*.h5)</source>
        <translation>HDF5 文件 (*.h5)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Open the export folder</source>
        <translation>打开导出文件夹</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Lag against swing frequency</source>
        <translation>滞后随摆动频率的变化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>swing frequency (Hz)</source>
        <translation>摆动频率 (Hz)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lag (ms), ±1σ</source>
        <translation>滞后 (ms)，±1σ</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>No frequency response yet.</source>
        <translation>尚无频率响应。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Result shown: %1</source>
        <translation>显示的结果：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;No delay:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;无延迟结果：&lt;/b&gt;%1</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>this run&apos;s, not recorded in a session; computed by fogbench %1 with %2</source>
        <translation>本次运行的结果，未记录到会话；由 fogbench %1 使用 %2 计算</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none stored in the session; computed by fogbench %1 with the session&apos;s constants (%2)</source>
        <translation>会话中未存储结果；由 fogbench %1 使用会话的常数（%2）计算</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>analysis</source>
        <translation>分析</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 of %2 · %6 · %3 · %4 · %5</source>
        <translation>%1/%2 · %6 · %3 · %4 · %5</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 of %2 · %3 · %4 · %5</source>
        <translation>%1 / %2 · %3 · %4 · %5</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> · damaged, cannot be shown</source>
        <translation> · 已损坏，无法显示</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Loading the chosen result …</source>
        <translation>正在载入所选结果 …</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>nominal</source>
        <translation>标称</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>table, 3-parameter</source>
        <translation>转台，三参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro, 3-parameter</source>
        <translation>陀螺，三参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table, 4-parameter</source>
        <translation>转台，四参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro, 4-parameter</source>
        <translation>陀螺，四参数</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>joint: lag as t₀</source>
        <translation>联合：以滞后为 t₀</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gain %1</source>
        <translation>增益 %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>measured lag (gyro behind table)</source>
        <translation>测得滞后（陀螺落后于转台）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>joint fit; CRLB %1 ms, σ/CRLB %2</source>
        <translation>联合拟合；CRLB %1 ms，σ/CRLB %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> — σ below the bound: understated (check uncertainty_below_bound)</source>
        <translation> — σ 低于克拉美–罗界：不确定度被低估（检查 uncertainty_below_bound）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>+ table read delay</source>
        <translation>+ 转台读数延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bench constant</source>
        <translation>测试台常数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>= IMU delay</source>
        <translation>= IMU 延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the paper: &lt; 0.8 ms</source>
        <translation>论文：&lt; 0.8 ms</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>− processing-board delay</source>
        <translation>− 处理板延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bench constant; theory: sampling, compensation, serial frame</source>
        <translation>测试台常数；理论：采样、补偿、串口帧</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>= gyro&apos;s own delay</source>
        <translation>= 陀螺自身延迟</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>sensing, loop and pulse update</source>
        <translation>敏感、闭环与脉冲更新</translation>
    </message>
    <message>
        <location line="+43"/>
        <source> (k %1)</source>
        <translation>（k %1）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>; this point: guard band %1 ms, P(true delay ≥ limit) %2</source>
        <translation>；本测试点：保护带 %1 ms，P(真实延迟 ≥ 限值) %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>; this point: no risk stated, its delay is refused</source>
        <translation>；本测试点：不给出风险，其延迟被拒绝</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ISO/IEC 17025:2017 §7.8.6 asks a statement of conformity to state its decision rule and risk; this one is ILAC-G8:09/2019&apos;s guarded acceptance: the guard band is k·σ, and 1 − Φ(k) is the largest probability that a delay accepted at the boundary truly reaches the limit (a Gaussian error with the stated σ)</source>
        <translation>ISO/IEC 17025:2017 §7.8.6 要求符合性声明写明所用的判定规则及其风险；此处为 ILAC-G8:09/2019 的保护带验收：保护带为 k·σ，1 − Φ(k) 是在验收边界上被接受的延迟其真值达到限值的最大概率（误差按所述 σ 的高斯分布）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>stored verdict</source>
        <translation>已保存的判定</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>verdict, not stored</source>
        <translation>判定（未保存）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Result: &lt;span style=&apos;color:%1&apos;&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/span&gt;</source>
        <translation>结果：&lt;span style=&apos;color:%1&apos;&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/span&gt;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> (incomplete run: %1; the data recorded give %2)</source>
        <translation>（运行不完整：%1；已记录的数据给出 %2）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>  ·  %1 (limit %2 ms)</source>
        <translation>  ·  %1（限值 %2 ms）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;br&gt;Test point: &lt;span style=&apos;color:%1&apos;&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/span&gt; (its data give %3): %4</source>
        <translation>&lt;br&gt;测试点：&lt;span style=&apos;color:%1&apos;&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/span&gt;（其数据给出 %3）：%4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;br&gt;Test point: &lt;span style=&apos;color:%1&apos;&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/span&gt;: %3</source>
        <translation>&lt;br&gt;测试点：&lt;span style=&apos;color:%1&apos;&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/span&gt;：%3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;br&gt;&lt;span style=&apos;color:#a05000&apos;&gt;This version&apos;s analysis of the same data with the stored settings differs from the stored result (%1); the verdict shown is the stored one. Re-analyse the session (Sessions) to store this version&apos;s result.&lt;/span&gt;</source>
        <translation>&lt;br&gt;&lt;span style=&apos;color:#a05000&apos;&gt;本版本用已保存的设置对同一数据的分析与已保存结果不同（%1）；显示的判定以已保存的为准。在“会话”中重新分析即可保存本版本的结果。&lt;/span&gt;</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&lt;b&gt;lag %1 ± %2 ms&lt;/b&gt;  ·  IMU delay %3 ms  ·  gyro&apos;s own delay %4 ms</source>
        <translation>&lt;b&gt;滞后 %1 ± %2 ms&lt;/b&gt;  ·  IMU 延迟 %3 ms  ·  陀螺自身延迟 %4 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;span style=&apos;color:%1&apos;&gt;&lt;b&gt;delay refused (%2)&lt;/b&gt;&lt;/span&gt;  ·  not vouched for: lag (%3 ms), IMU delay (%4 ms)</source>
        <translation>&lt;span style=&apos;color:%1&apos;&gt;&lt;b&gt;延迟被拒绝（%2）&lt;/b&gt;&lt;/span&gt;  ·  不可担保：滞后（%3 ms），IMU 延迟（%4 ms）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>  ·  simulator truth: lag %1 ms</source>
        <translation>  ·  仿真真值：滞后 %1 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  ·  &lt;span style=&apos;color:#b00000&apos;&gt;incomplete run&lt;/span&gt;</source>
        <translation>  ·  &lt;span style=&apos;color:#b00000&apos;&gt;运行未完成&lt;/span&gt;</translation>
    </message>
    <message>
        <location line="+113"/>
        <source>+ fitted lag %1 ms, refused (%2)</source>
        <translation>+ 拟合滞后 %1 ms，被拒绝（%2）</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>There is no delay result to export.</source>
        <translation>没有可导出的延迟结果。</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+23"/>
        <source>There is no result to export.</source>
        <translation>没有可导出的结果。</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>There is no frequency response to export: %1</source>
        <translation>没有可导出的频率响应：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 cannot hold both the points and the models; choose another name.</source>
        <translation>%1 不能同时保存测试点和模型；请另选文件名。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Nothing was exported: the models go beside the points as %1, and that file already exists. It was not named in the dialog and is not replaced: move or delete it, or choose another name for the points.</source>
        <translation>未导出任何内容：模型写在测试点旁，即 %1，而该文件已存在。它不是在对话框中指定的文件，不会被替换：请移走或删除它，或为测试点另选文件名。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1
The points were written to %2; the models were not.</source>
        <translation>%1
测试点已写入 %2；模型未写入。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>There is no Bode plot to export: %1</source>
        <translation>没有可导出的伯德图：%1</translation>
    </message>
    <message>
        <location line="-218"/>
        <location line="+8"/>
        <location line="+48"/>
        <source>table</source>
        <translation>转台</translation>
    </message>
    <message>
        <location line="-157"/>
        <source>Decision rule: PASS when IMU delay + k·σ &lt; limit (k = %1, guarded acceptance); false-accept risk ≤ 1 − Φ(k) = %2</source>
        <translation>判定规则：IMU 延迟 + k·σ &lt; 限值时合格（k = %1，保护带验收）；误接受风险 ≤ 1 − Φ(k) = %2</translation>
    </message>
    <message>
        <location line="+102"/>
        <location line="+56"/>
        <source>gyro (integrated, trend removed)</source>
        <translation>陀螺（积分，已去除趋势）</translation>
    </message>
    <message>
        <location line="-55"/>
        <location line="+57"/>
        <source>table fit</source>
        <translation>转台拟合</translation>
    </message>
    <message>
        <location line="-55"/>
        <location line="+58"/>
        <source>gyro fit</source>
        <translation>陀螺拟合</translation>
    </message>
    <message>
        <location line="-55"/>
        <source>gyro</source>
        <translation>陀螺</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>table crosses zero</source>
        <translation>转台过零</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>+ fitted lag %1 ms</source>
        <translation>+ 拟合滞后 %1 ms</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1 axis</source>
        <translation>%1 轴</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: weighted %2 ms, %3 with a pure delay (p = %4)</source>
        <translation>%1：加权 %2 ms，与纯延迟%3（p = %4）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>consistent</source>
        <translation>一致</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NOT consistent</source>
        <translation>不一致</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; %1 refused test point(s) left out</source>
        <translation>；未计入 %1 个被拒绝的测试点</translation>
    </message>
</context>
<context>
    <name>fog::ui::SeriesPlot</name>
    <message>
        <location filename="../../ui/plots/series_plot.cpp" line="+41"/>
        <source>time (s)</source>
        <translation>时间 (s)</translation>
    </message>
</context>
<context>
    <name>fog::ui::SessionBrowser</name>
    <message>
        <location filename="../../ui/session_browser.cpp" line="+29"/>
        <source>all refused</source>
        <translation>全部被拒绝</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, %1 refused</source>
        <translation>，%1 个被拒绝</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Folder</source>
        <translation>文件夹</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Choose…</source>
        <translation>选择…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>刷新</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>File</source>
        <translation>文件</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Recorded (UTC)</source>
        <translation>记录时间 (UTC)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>IMU</source>
        <translation>IMU</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Axes</source>
        <translation>轴</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Lag (ms)</source>
        <translation>滞后 (ms)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>IMU delay (ms)</source>
        <translation>IMU 延迟 (ms)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Open (read-only)</source>
        <translation>打开（只读）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Re-analyse with the bench constants</source>
        <translation>按测试台常数重新分析</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Adds a new result to the session, analysed with the bench constants, gyro signs and limit (Tools → Bench constants); its raw data and earlier results never change</source>
        <translation>按测试台常数、陀螺符号和限值（工具 → 测试台常数）分析，并向会话添加一个新结果；其原始数据和先前的结果都不会改变</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Compare the selected</source>
        <translation>比较所选会话</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Two sessions: their delays per test point and the difference with its significance (A is the session chosen first, B the second); more sessions of one IMU: the delay against the date as well</source>
        <translation>两个会话：各测试点的延迟及其差值和显著性（A 为先选的会话，B 为后选的）；同一 IMU 的多个会话：另给出延迟随日期的变化</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Import CSV data…</source>
        <translation>导入 CSV 数据…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data from another bench (metadata.json, table.csv, gyro.csv) becomes a session here</source>
        <translation>将其他测试台的数据（metadata.json、table.csv、gyro.csv）导入为此处的会话</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Session folder</source>
        <translation>会话文件夹</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Folder with metadata.json, table.csv, gyro.csv</source>
        <translation>包含 metadata.json、table.csv、gyro.csv 的文件夹</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Choose the folder that holds the session files (.fbs).</source>
        <translation>请选择存放会话文件（.fbs）的文件夹。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No sessions yet: %1 is made when the first session is recorded. Run a test plan (Run), or choose a folder that holds session files.</source>
        <translation>尚无会话：记录第一个会话时将创建 %1。请运行测试计划（运行），或选择存有会话文件的文件夹。</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>unreadable: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>, %1 points</source>
        <translation>，%1 个测试点</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>complete</source>
        <translation>完成</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>incomplete: %1</source>
        <translation>未完成：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1; raw stream damaged: restore the file from a backup</source>
        <translation>%1；原始数据流已损坏：请从备份恢复文件</translation>
    </message>
    <message numerus="yes">
        <location line="+15"/>
        <source>%n session(s)</source>
        <translation>
            <numerusform>%n 个会话</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n unreadable (the reason is in the State column)</source>
        <translation>
            <numerusform>%n 个无法读取（原因见“状态”列）</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n other file(s) skipped</source>
        <translation>
            <numerusform>跳过其他文件 %n 个</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>fog::ui::TablePanel</name>
    <message>
        <location filename="../../ui/table_panel.cpp" line="+23"/>
        <source>idle</source>
        <translation>空闲</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>moving</source>
        <translation>运动中</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+557"/>
        <source>emergency stop</source>
        <translation>急停</translation>
    </message>
    <message>
        <location line="-556"/>
        <location line="+2"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>moving %1 to %2°</source>
        <translation>将 %1 轴转到 %2°</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the stop</source>
        <translation>停止指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the emergency stop</source>
        <translation>急停指令</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The controller refuses %1: the table is moving (settings conflict); wait for the move to end or press Stop.</source>
        <translation>控制器拒绝%1：转台正在运动（设置冲突）；请等待运动结束，或按“停止”。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The controller refuses %1: the position is beyond what it accepts (data out of range: %2).</source>
        <translation>控制器拒绝%1：位置超出其允许范围（数据超出范围：%2）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The controller refuses %1: its interlock is open (a door or a guard); close it, then try again.</source>
        <translation>控制器拒绝%1：其联锁已断开（门或防护装置）；请关闭后重试。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The controller refuses %1: its emergency stop is engaged; reset it at the controller first.</source>
        <translation>控制器拒绝%1：其急停已生效；请先在控制器处复位。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The controller refuses %1: it missed the bench&apos;s heartbeat and stopped the table; disconnect and connect again.</source>
        <translation>控制器拒绝%1：它未收到测试台的心跳，已停止转台；请断开后重新连接。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The controller does not understand %1 (%2); does it speak the bench&apos;s table protocol (docs/table-control.md)?</source>
        <translation>控制器无法理解%1（%2）；它是否使用测试台的转台协议（docs/table-control.md）？</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The controller refuses %1 (%2).</source>
        <translation>控制器拒绝%1（%2）。</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+195"/>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="-149"/>
        <source>axis</source>
        <translation>轴</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>state</source>
        <translation>状态</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Home</source>
        <translation>回零</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Jog step</source>
        <translation>点动步长</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+15"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Go to</source>
        <translation>转到</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Go</source>
        <translation>执行</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>EMERGENCY STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>No table address: choose Table ▸ Remote controller in Configure and give its address (tcp:HOST:PORT or a serial device).</source>
        <translation>没有转台地址：请在“配置”中选择 转台 ▸ 远程控制器 并填写其地址（tcp:主机:端口 或串口设备）。</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Cannot connect to the table: %1</source>
        <translation>无法连接转台：%1</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Stop sent: every axis decelerates to rest.</source>
        <translation>停止指令已发送：所有轴减速至静止。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 did not reach the controller: %2</source>
        <translation>%1未到达控制器：%2</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>A run drives the table; stop it first.</source>
        <translation>运行正在驱动转台；请先停止运行。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The table is not connected yet; the table was not moved.</source>
        <translation>转台尚未连接；转台未运动。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The table does not answer (%1); the table was not moved.</source>
        <translation>转台无应答（%1）；转台未运动。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The table has not answered for %1 s; the table was not moved.</source>
        <translation>转台已 %1 s 无应答；转台未运动。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The table cannot move: %1; the table was not moved.</source>
        <translation>转台不能运动：%1；转台未运动。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 to %2°</source>
        <translation>%1 轴转到 %2°</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>A run drives the table; stop the run (tool bar) instead.</source>
        <translation>运行正在驱动转台；请改为停止运行（工具栏）。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Stopping every axis…</source>
        <translation>正在停止所有轴…</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>EMERGENCY STOP: sending…</source>
        <translation>急停：正在发送…</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Stop sent %1 ms after the click on a connection of its own: every axis decelerates to rest (the panel&apos;s connection confirms it once the controller answers).</source>
        <translation>停止指令已在点击后 %1 ms 通过其专用连接发送：所有轴减速至静止（控制器应答后，面板的连接将予以确认）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The stop&apos;s own connection failed (%1); it waits in the panel&apos;s connection until the controller answers. If the table must stop now, use the emergency stop.</source>
        <translation>停止指令的专用连接失败（%1）；它在面板的连接中等待，直到控制器应答。如需转台立即停止，请使用急停。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Reset it at the controller before the table moves again.</source>
        <translation>转台再次运动前，请在控制器处复位。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Emergency stop sent: every axis stops.</source>
        <translation>急停指令已发送：所有轴停止。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The emergency stop did not reach the controller: %1. Use the table&apos;s own stop button.</source>
        <translation>急停指令未到达控制器：%1。请使用转台自身的停止按钮。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Emergency stop sent %1 ms after the click on a connection of its own; the controller reports it engaged: every axis stops.</source>
        <translation>急停指令已在点击后 %1 ms 通过独立连接发送；控制器报告急停已生效：所有轴停止。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Emergency stop sent %1 ms after the click on a connection of its own, but the controller has not confirmed it (%2). Watch the table; if it still moves, use its own stop button.</source>
        <translation>急停指令已在点击后 %1 ms 通过独立连接发送，但控制器尚未确认（%2）。请注意观察转台；若仍在运动，请使用转台自身的停止按钮。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The emergency stop&apos;s own connection failed (%1), but it reached the controller through the panel&apos;s connection: every axis stops.</source>
        <translation>急停的独立连接失败（%1），但急停指令已通过面板的连接到达控制器：所有轴停止。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The emergency stop did not reach the controller: its own connection failed (%1) and so did the panel&apos;s (%2). Use the table&apos;s own stop button.</source>
        <translation>急停指令未到达控制器：其独立连接失败（%1），面板的连接也失败（%2）。请使用转台自身的停止按钮。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The emergency stop&apos;s own connection failed (%1); it waits in the panel&apos;s connection until the controller answers. If the table still moves, use its own stop button.</source>
        <translation>急停的独立连接失败（%1）；急停指令在面板的连接中等待控制器应答。若转台仍在运动，请使用转台自身的停止按钮。</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>no answer</source>
        <translation>无应答</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Every axis decelerates to rest (not latched); a move still queued is dropped</source>
        <translation>所有轴减速至静止（不锁定）；仍在排队的运动指令将被丢弃</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop every axis at once, on a connection of its own and through the panel&apos;s (latched at the controller)</source>
        <translation>通过独立连接并经面板的连接立即停止所有轴（在控制器处锁定）</translation>
    </message>
    <message>
        <location line="-72"/>
        <source>No table is connected: press Connect (the address is the Configure view&apos;s remote table).</source>
        <translation>未连接转台：请按“连接”（地址取自“配置”视图中的远程转台）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A run drives the table; only the emergency stop is available.</source>
        <translation>运行正在驱动转台；只有急停可用。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connecting to the table…</source>
        <translation>正在连接转台…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The table does not answer; only the emergency stop is available.</source>
        <translation>转台无应答；只有急停可用。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The table has not answered for %1 s; only the emergency stop is available.</source>
        <translation>转台已 %1 s 无应答；只有急停可用。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>No table connected.</source>
        <translation>未连接转台。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Connecting to %1…</source>
        <translation>正在连接 %1…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connecting to %1: no answer for %2 s…</source>
        <translation>正在连接 %1：已 %2 s 无应答…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: no answer for %2 s</source>
        <translation>%1：已 %2 s 无应答</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Unreachable: %1</source>
        <translation>无法访问：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No answer for %1 s (%2); reconnecting to %3…</source>
        <translation>已 %1 s 无应答（%2）；正在重新连接 %3…</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>unreachable</source>
        <translation>无法访问</translation>
    </message>
</context>
<context>
    <name>fog::ui::UnitsView</name>
    <message>
        <location filename="../../ui/units_view.cpp" line="+93"/>
        <source>%1 %2 Hz</source>
        <translation>%1 %2 Hz</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 ± %3 ms %4</source>
        <translation>%1：%2 ± %3 ms %4</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: refused (%2)</source>
        <translation>%1：被拒绝（%2）</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>IMU delay (ms), ±1σ</source>
        <translation>IMU 延迟（ms），±1σ</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>No catalog at %1 yet. Index folder… makes one from the sessions of a folder; Open catalog… opens another.</source>
        <translation>%1 处尚无目录。“索引文件夹…”可由一个文件夹中的会话建立目录；“打开目录…”可打开其他目录。</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Catalog</source>
        <translation>目录</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a catalog file (.sqlite), a sessions folder, or postgresql://…</source>
        <translation>目录文件（.sqlite）、会话文件夹或 postgresql://…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>By default the catalog of the sessions folder (fogbench-catalog.sqlite there). A PostgreSQL address (postgresql://host/db) shows a catalog shared by benches.</source>
        <translation>默认使用会话文件夹中的目录（其中的 fogbench-catalog.sqlite）。PostgreSQL 地址（postgresql://host/db）显示多个测试台共享的目录。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open catalog…</source>
        <translation>打开目录…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Index folder…</source>
        <translation>索引文件夹…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reads the sessions under a folder into this catalog, in the background; files unchanged since they were last indexed are not read again</source>
        <translation>在后台将文件夹下的会话读入此目录；自上次索引以来未改变的文件不再重读</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reload</source>
        <translation>重新读取</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>IMU serial</source>
        <translation>IMU 序列号</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Lots</source>
        <translation>批次</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Benches</source>
        <translation>测试台</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Sessions</source>
        <translation>会话</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Results</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Latest session (UTC)</source>
        <translation>最近会话（UTC）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Its verdict</source>
        <translation>其判定</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Lot</source>
        <translation>批次</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Open in Results</source>
        <translation>在“结果”中打开</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Opens the chosen result&apos;s session read-only in Results (double-click a row does the same); Results shows its newest result, the others are chosen there</source>
        <translation>以只读方式在“结果”中打开所选结果的会话（双击一行效果相同）；“结果”显示其最新结果，其他结果可在那里选择</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Session (UTC)</source>
        <translation>会话（UTC）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bench</source>
        <translation>测试台</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temp. (°C)</source>
        <translation>温度（°C）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>IMU delay per test point</source>
        <translation>各测试点的 IMU 延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Constants</source>
        <translation>常数</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Software</source>
        <translation>软件</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Analysed by</source>
        <translation>分析者</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>IMU delay against the session date</source>
        <translation>IMU 延迟随会话日期</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>session recorded (UTC)</source>
        <translation>会话记录时间（UTC）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>IMU delay against the IMU temperature</source>
        <translation>IMU 延迟随 IMU 温度</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>mean IMU temperature (°C)</source>
        <translation>IMU 平均温度（°C）</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Indexing %1: %2 of %3 files…</source>
        <translation>正在索引 %1：%3 个文件中的第 %2 个…</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+119"/>
        <source>Indexing %1: looking for session files…</source>
        <translation>正在索引 %1：查找会话文件…</translation>
    </message>
    <message>
        <location line="-107"/>
        <source>Open catalog</source>
        <translation>打开目录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Catalogs (*.sqlite *.db);;All files (*)</source>
        <translation>目录 (*.sqlite *.db);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Folder of sessions to index</source>
        <translation>要索引的会话文件夹</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Choose a catalog: the sessions folder&apos;s, a catalog file, or a PostgreSQL address.</source>
        <translation>请选择目录：会话文件夹的目录、目录文件或 PostgreSQL 地址。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Reading %1…</source>
        <translation>正在读取 %1…</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The catalog could not be read.</source>
        <translation>无法读取目录。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: %2 results of %3 units.</source>
        <translation>%1：%3 个单元的 %2 个结果。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 files refused when indexed (unreadable or damaged): `fogbench-cli catalog refused` lists them with why.</source>
        <translation>索引时拒绝了 %1 个文件（无法读取或已损坏）：`fogbench-cli catalog refused` 列出它们及原因。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>An indexing is under way; it ends before another starts.</source>
        <translation>索引正在进行；须待其结束后才能开始新的索引。</translation>
    </message>
    <message>
        <location line="+46"/>
        <location line="+2"/>
        <source>Indexing %1 failed</source>
        <translation>索引 %1 失败</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+18"/>
        <source>Index folder</source>
        <translation>索引文件夹</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Indexed %1: %2 session files, %3 read (%4 results), %5 unchanged, %6 refused</source>
        <translation>已索引 %1：会话文件 %2 个，读取 %3 个（%4 个结果），未改变 %5 个，拒绝 %6 个</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 files were refused and are not in the catalog</source>
        <translation>%1 个文件被拒绝，未收入目录</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A refused file is read again at the next indexing once it changes; restore a damaged one from a backup.</source>
        <translation>被拒绝的文件改变后会在下次索引时重新读取；损坏的文件请从备份恢复。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>All lots</source>
        <translation>所有批次</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Pass rate: %1.
First-pass yield: %2.
IMU delay mean and s: %3.
Cpk: %4.</source>
        <translation>通过率：%1。
一次通过率：%2。
IMU 延迟均值与 s：%3。
Cpk：%4。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Choose a lot for its statistics: pass rate, first-pass yield, the IMU delay&apos;s mean and spread, Cpk against the limit.</source>
        <translation>选择一个批次以查看其统计：通过率、一次通过率、IMU 延迟的均值与离散、相对限值的 Cpk。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Lot %1: %2</source>
        <translation>批次 %1：%2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 % (%2 of %3)</source>
        <translation>%1 %（%3 个中的 %2 个）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;Lot %1&lt;/b&gt;: %2 units, %3 sessions</source>
        <translation>&lt;b&gt;批次 %1&lt;/b&gt;：%2 个单元，%3 个会话</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;span style=&apos;color:%1&apos;&gt;%2 %3&lt;/span&gt;, &lt;span style=&apos;color:%4&apos;&gt;%5 %6&lt;/span&gt;, &lt;span style=&apos;color:%7&apos;&gt;%8 %9&lt;/span&gt;, %10 %11</source>
        <translation>&lt;span style=&apos;color:%1&apos;&gt;%2 %3&lt;/span&gt;，&lt;span style=&apos;color:%4&apos;&gt;%5 %6&lt;/span&gt;，&lt;span style=&apos;color:%7&apos;&gt;%8 %9&lt;/span&gt;，%10 %11</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 superseded results (re-analysed) not counted</source>
        <translation>%1 个已被取代的结果（已重新分析）不计入</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pass rate: %1</source>
        <translation>通过率：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First-pass yield: %1</source>
        <translation>一次通过率：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 ms (%2)</source>
        <translation>%1 ms（%2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no limit</source>
        <translation>无限值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>IMU delay %1: %2 points, mean %3 ms, s %4 ms, Cpk %5</source>
        <translation>IMU 延迟 %1：%2 个点，均值 %3 ms，s %4 ms，Cpk %5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>all axes</source>
        <translation>所有轴</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>IMU delay: no vouched test point in this lot</source>
        <translation>IMU 延迟：此批次中没有可担保的测试点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cpk against %1; definitions in the tooltip</source>
        <translation>Cpk 相对于 %1；定义见工具提示</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Choose a unit for its history.</source>
        <translation>选择一个单元以查看其历史。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1
result analysed %2</source>
        <translation>%1
结果分析于 %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1, shown</source>
        <translation>%1，显示中</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1, superseded</source>
        <translation>%1，已被取代</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The session&apos;s shown result</source>
        <translation>该会话显示的结果</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>A later analysis of the same session is shown</source>
        <translation>显示的是同一会话的较新分析</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>(no serial)</source>
        <translation>（无序列号）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;b&gt;%1&lt;/b&gt;%2: %3 results, oldest session first (%4 superseded by a later analysis of their session); the plots show the shown results</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;%2：%3 个结果，最早的会话在前（%4 个已被其会话的较新分析取代）；曲线图显示各会话显示中的结果</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>refused (INVALID or INCOMPLETE): no delay</source>
        <translation>被拒绝（无效或不完整）：无延迟</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>slope %1 ± %2 µs/°C over %3 points</source>
        <translation>斜率 %1 ± %2 µs/°C（%3 个点）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>slope: needs 3 or more vouched points at two or more temperatures (has %1)</source>
        <translation>斜率：需要在两个或以上温度下的 3 个或以上可担保的点（现有 %1 个）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 results without a temperature not plotted</source>
        <translation>%1 个无温度的结果未绘制</translation>
    </message>
</context>
<context>
    <name>core_text</name>
    <message>
        <location filename="../../ui/core_text.cpp" line="+25"/>
        <source>table</source>
        <translation>转台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro</source>
        <translation>陀螺</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro-table</source>
        <translation>陀螺−转台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timing</source>
        <translation>时序</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>imu</source>
        <translation>IMU</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexplained</source>
        <translation>无法解释</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bias_drift</source>
        <translation>零偏漂移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scale_factor_error</source>
        <translation>标度因数误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scale_factor_asymmetry</source>
        <translation>标度因数不对称</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scale_factor_nonlinearity</source>
        <translation>标度因数非线性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>misalignment</source>
        <translation>安装失准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>g_sensitivity</source>
        <translation>g 敏感性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>first_order_lag</source>
        <translation>一阶滞后</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table_harmonic_distortion</source>
        <translation>转台运动谐波失真</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>encoder_cyclic_error</source>
        <translation>编码器周期误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timestamp_jitter</source>
        <translation>时间戳抖动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>clock_drift</source>
        <translation>时钟漂移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dropped_frames</source>
        <translation>丢帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>earth_rate_projection</source>
        <translation>地球自转角速度投影</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bias drift</source>
        <translation>零偏漂移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scale-factor error</source>
        <translation>标度因数误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scale-factor asymmetry</source>
        <translation>标度因数不对称</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scale-factor nonlinearity</source>
        <translation>标度因数非线性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>g-sensitivity</source>
        <translation>g 敏感性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>first-order lag</source>
        <translation>一阶滞后</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table harmonic distortion</source>
        <translation>转台运动谐波失真</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>encoder cyclic error</source>
        <translation>编码器周期误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time-stamp jitter</source>
        <translation>时间戳抖动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU clock drift</source>
        <translation>IMU 时钟漂移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dropped frames</source>
        <translation>丢帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Earth-rate projection</source>
        <translation>地球自转角速度投影</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none (the recording agrees with the simulation)</source>
        <translation>无（记录与仿真一致）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexplained (no effect of the library closes the gap)</source>
        <translation>无法解释（效应库中没有效应能消除差异）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>harmonic %1, in phase</source>
        <translation>%1 次谐波，同相</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>harmonic %1, quadrature</source>
        <translation>%1 次谐波，正交</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>residual mean square</source>
        <translation>残差均方</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cross-axis, in phase</source>
        <translation>交叉轴，同相</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cross-axis, quadrature</source>
        <translation>交叉轴，正交</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table stamp interval</source>
        <translation>转台时间戳间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table stamp-interval variance</source>
        <translation>转台时间戳间隔方差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU stamp interval</source>
        <translation>IMU 时间戳间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU stamp-interval variance</source>
        <translation>IMU 时间戳间隔方差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU frames lost</source>
        <translation>IMU 丢帧数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table samples lost</source>
        <translation>转台丢失样本数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>h%1_in_phase</source>
        <translation>%1 次谐波同相</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>h%1_quadrature</source>
        <translation>%1 次谐波正交</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>residual_ms</source>
        <translation>残差均方</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gain</source>
        <translation>增益</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>delay</source>
        <translation>延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>trend</source>
        <translation>趋势</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cross_in_phase</source>
        <translation>交叉轴同相</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cross_quadrature</source>
        <translation>交叉轴正交</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table_interval</source>
        <translation>转台采样间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table_interval_var</source>
        <translation>转台采样间隔方差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>imu_interval</source>
        <translation>IMU 帧间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>imu_interval_var</source>
        <translation>IMU 帧间隔方差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>imu_lost</source>
        <translation>IMU 丢帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table_lost</source>
        <translation>转台丢样</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frames</source>
        <translation>帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drift</source>
        <translation>漂移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scale_factor</source>
        <translation>标度因数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>asymmetry</source>
        <translation>不对称度</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>h2</source>
        <translation>二次谐波</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>h3</source>
        <translation>三次谐波</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>nonlinearity</source>
        <translation>非线性度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time_constant</source>
        <translation>时间常数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sin_amplitude</source>
        <translation>正弦幅值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cos_amplitude</source>
        <translation>余弦幅值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>jitter_variance</source>
        <translation>抖动方差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>loss_rate</source>
        <translation>丢帧率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>latitude_error</source>
        <translation>纬度误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heading_error</source>
        <translation>航向误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg/h per min</source>
        <translation>°/h 每分钟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ppm at 100 deg/s</source>
        <translation>ppm（100 °/s 处）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ppm of full scale over +-100 deg/s</source>
        <translation>满量程 ppm（±100 °/s 范围）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>per mille</source>
        <translation>‰</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arcsec</source>
        <translation>角秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sim-to-real diagnosis: %1 gap-map cells, chi2 %2 (%3)</source>
        <translation>仿真与实测差异诊断：差异图 %1 格，chi2 %2（%3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>significant gap</source>
        <translation>差异显著</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no significant gap</source>
        <translation>无显著差异</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>replay calibrated to: lag %1 ms, table frequency %2 ppm, encoder noise %3 deg, ARW %4 deg/sqrt(h), bias %5 deg/h,</source>
        <translation>回放校准为：滞后 %1 ms，转台频率 %2 ppm，编码器噪声 %3 deg，ARW %4 deg/sqrt(h)，零偏 %5 deg/h，</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>z %1, heading %2 +- %3 deg, table every %4 ms, IMU every %5 ms, bias instability %6 deg/h over %7 s (%8)</source>
        <translation>z 轴%1，航向 %2 ± %3 deg，转台每 %4 ms、IMU 每 %5 ms 一个样本，零偏不稳定性 %6 deg/h、相关时间 %7 s（%8）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stated</source>
        <translation>已给定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>assumed</source>
        <translation>假定值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timing audit real replay</source>
        <translation>时序审核&#x3000;&#x3000;&#x3000;&#x3000;&#x3000;&#x3000;实测&#x3000;&#x3000;&#x3000;&#x3000;&#x3000;&#x3000;&#x3000;&#x3000;&#x3000;回放</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 interval %2 ppm, std %3 us, gaps %4, dup %5 | %6 ppm, std %7 us, gaps %8</source>
        <translation>%1 间隔 %2 ppm，标准差 %3 µs，缺口 %4，重复 %5 | %6 ppm，标准差 %7 µs，缺口 %8</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lost %1 / %2, duplicates %3 / %4, wraps %5 / %6, checksum failures %7 / %8</source>
        <translation>丢失 %1 / %2，重复 %3 / %4，计数器回绕 %5 / %6，校验失败 %7 / %8</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gap per channel (rms z; 1 = within the simulator&apos;s spread) before after held-out shrink</source>
        <translation>各通道差异（z 的均方根；1 = 在仿真离散度之内）&#x3000;之前&#x3000;之后&#x3000;留出数据缩减</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 cells %3 %4 %5 %</source>
        <translation>%1 %2 格&#x3000;%3 %4 %5 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest cells:</source>
        <translation>最大的格：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point %1 segment %2 %3 %4 axis %5: real %6, replay %7 +- %8 %9 (z %10)</source>
        <translation>点 %1 段 %2 %3 %4 轴 %5：实测 %6，回放 %7 ± %8 %9（z %10）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Effects, ranked (score = training delta chi2 - k ln n)</source>
        <translation>候选效应排序（得分 = 训练数据的 Δchi2 − k ln n）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 score %2 held-out shrink %3 % KEPT %4</source>
        <translation>%1 得分 %2&#x3000;留出缩减 %3 %&#x3000;保留&#x3000;%4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 score %2 held-out shrink %3 % %4</source>
        <translation>%1 得分 %2&#x3000;留出缩减 %3 %&#x3000;%4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 +- %3 %4, %5</source>
        <translation>%1 %2 ± %3 %4，%5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 +- %3 %4</source>
        <translation>%1 %2 ± %3 %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Alias groups (swing data cannot separate these)</source>
        <translation>混叠组（摆动数据无法区分组内各项）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>to separate: %1</source>
        <translation>区分方法：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>note: %1</source>
        <translation>注：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Verdict: %1 (+ %2) - %3</source>
        <translation>结论：%1（+ %2）—— %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Verdict: %1 - %2</source>
        <translation>结论：%1 —— %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(diagnosis took %1 s)</source>
        <translation>（诊断用时 %1 s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>constant delay: %1</source>
        <translation>恒定延迟：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>constant rate: %1</source>
        <translation>恒定角速度：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pure gyro delay, first-order lag with time constant &lt;= 5 ms, table read delay, timestamp offset, fixed serial / board latency</source>
        <translation>纯陀螺延迟、时间常数 ≤ 5 ms 的一阶滞后、转台读数延迟、时间戳偏移、固定的串口 / 采样板延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro bias, earth_rate_projection (latitude / heading error)</source>
        <translation>陀螺零偏、地球自转角速度投影（纬度 / 航向误差）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lag %1 ms (taken as the replay&apos;s nominal delay)</source>
        <translation>滞后 %1 ms（作为回放的标称延迟）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bias %1 / %2 / %3 deg/h (X/Y/Z, over the nominal Earth rate)</source>
        <translation>零偏 %1 / %2 / %3 deg/h（X/Y/Z，扣除标称地球自转角速度后）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>swing data shift all of them by one constant at every frequency: measure the read delay and the board latency on the board (loop-back / sync pulse), and separate a lag from a delay with a step or a swing above 1/(2 pi tau) (~30 Hz for 5 ms)</source>
        <translation>摆动数据在每个频率上都把它们移动同一个常数：在采样板上测量读数延迟和板延迟（回环 / 同步脉冲），用阶跃或高于 1/(2πτ) 的摆动（5 ms 时约 30 Hz）区分滞后与延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a constant rate per axis looks the same either way: a multi-position static test (IMU turned to four headings) separates the Earth rate from the bias</source>
        <translation>每轴的恒定角速度两种来源看起来相同：多位置静态试验（IMU 转到四个航向）可区分地球自转角速度与零偏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gap is significant and no effect in the library closes it on held-out blocks</source>
        <translation>差异显著，效应库中没有任何效应能在留出数据上消除它</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>real and simulated data agree within the simulator&apos;s own spread</source>
        <translation>实测与仿真在仿真自身的离散度之内一致</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 closes %2 % of the held-out gap but leaves a significant remainder in the %3; the rest is not in the library</source>
        <translation>%1 消除了留出数据差异的 %2 %，但在%3中留下显著的剩余；其余部分不在效应库中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>closes %1 % of the held-out gap</source>
        <translation>消除了留出数据差异的 %1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gap is significant and no effect in the library explains it: the best, %1, closes only %2 % of the held-out gap and leaves a significant remainder in the %3</source>
        <translation>差异显著，效应库中没有效应能解释它：最佳的 %1 只缩小了留出差异的 %2 %，且在%3中留下显著残差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>with the IMU&apos;s z axis %1 instead, a g-sensitivity of %2 deg/h/g gives the same data as %3 deg/h/g in the frame used: an isotropic g-sensitivity adds to the vertical Earth rate and swing data cannot tell them apart</source>
        <translation>若 IMU 的 z 轴改为%1，%2 °/h/g 的 g 敏感性给出与所用坐标系中 %3 °/h/g 相同的数据：各向同性的 g 敏感性叠加在垂直地球自转角速度上，摆动数据无法区分二者</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>check the IMU&apos;s mounting (a static test with the IMU turned over separates them)</source>
        <translation>请检查 IMU 的安装（将 IMU 翻转后做静态测试可区分二者）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the table channel&apos;s harmonics are in the encoder&apos;s reading only: the share of the table&apos;s harmonics the gyros do not see is %1 +- %2 (0 for a motion of the table, 1 for an encoder reading error), %3 sigma from a motion</source>
        <translation>转台通道的谐波只存在于编码器读数中：陀螺未看到的转台谐波份额为 %1 ± %2（转台运动为 0，编码器读数误差为 1），与运动相差 %3 σ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an encoder reading error (an eccentric grating, a read-head error) is not in the library, whose table harmonic distortion is a motion and is kept as the table channel&apos;s partial explanation</source>
        <translation>编码器读数误差（光栅偏心、读数头误差）不在效应库中；库中的转台谐波畸变是一种运动，作为转台通道的部分解释保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fits the table channel, but the gyros do not see its harmonics: a reading error, not a motion</source>
        <translation>拟合了转台通道，但陀螺未看到其谐波：是读数误差，而不是运动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an encoder reading error with the same harmonics is not excluded: the share of the table&apos;s harmonics the gyros do not see is %1 +- %2 (0 for a motion of the table, 1 for an encoder reading error)</source>
        <translation>不能排除具有相同谐波的编码器读数误差：陀螺未看到的转台谐波份额为 %1 ± %2（转台运动为 0，编码器读数误差为 1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a second read head opposite the first, or an autocollimator on the table, separates a reading error from a motion</source>
        <translation>在第一个读数头对面加装第二个读数头，或在转台上使用自准直仪，可区分读数误差与运动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 channel (%2)</source>
        <translation>%1 通道（%2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>held-out cells (%1)</source>
        <translation>留出格（%1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>excess chi2 %1 over %2 cells, %3 sigma</source>
        <translation>%2 格上超出 chi2 %1，%3 σ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 lost IMU frames filled with the mean increment</source>
        <translation>%1 个丢失的 IMU 帧以平均增量填补</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the noise model fits the Allan curve poorly (chi^2 %1 for %2 dof): a term outside IEEE 952, or non-white quantisation</source>
        <translation>噪声模型与 Allan 曲线拟合不佳（%2 个自由度 chi^2 为 %1）：存在 IEEE 952 之外的噪声项，或量化噪声不是白噪声</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>quantisation</source>
        <translation>量化噪声</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>angle random walk</source>
        <translation>角度随机游走</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bias instability</source>
        <translation>零偏不稳定性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rate random walk</source>
        <translation>角速度随机游走</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rate ramp</source>
        <translation>角速度斜坡</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>simulator, seed %1, %2</source>
        <translation>仿真器，种子 %1，%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>session %1 (%2)</source>
        <translation>会话 %1（%2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>result %1 of %2, stored %3 by %4 (fogbench %5)</source>
        <translation>结果 %1/%2，%3 由 %4 保存（fogbench %5）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>acquisition</source>
        <translation>采集</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sagnac sensing</source>
        <translation>Sagnac 敏感</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>instantaneous in principle</source>
        <translation>原理上是瞬时的</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>closed-loop delay</source>
        <translation>闭环延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;= %1 eigen periods</source>
        <translation>≤ %1 个本征周期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pulse output update</source>
        <translation>脉冲输出更新</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 .. one update period</source>
        <translation>0 … 一个更新周期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>board: pulse sampling</source>
        <translation>处理板：脉冲采样</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>board clock cycles</source>
        <translation>处理板时钟周期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>board: temperature compensation</source>
        <translation>处理板：温度补偿</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>board: serial frame</source>
        <translation>处理板：串行帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 bytes at %2 baud</source>
        <translation>%1 字节，%2 波特</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>real time</source>
        <translation>实时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>as fast as possible</source>
        <translation>尽可能快</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1x real time</source>
        <translation>%1 倍实时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>preset %1</source>
        <translation>预设 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>simulator truth, test point %1: lag %2 ms</source>
        <translation>仿真真值，测试点 %1：滞后 %2 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>replay of %1 at as fast as possible</source>
        <translation>回放 %1，尽可能快</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>replay of %1 at %2x</source>
        <translation>回放 %1，%2 倍速</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>replay of %1 at as fast as possible (%2)</source>
        <translation>回放 %1，尽快（%2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>replay of %1 at %2x (%3)</source>
        <translation>回放 %1，%2 倍速（%3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped by the operator after %1 s</source>
        <translation>操作员在 %1 s 后停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recording was interrupted: the recording program stopped without finishing the session (crash, kill, power cut or a full disk); everything committed until then is kept</source>
        <translation>记录被中断：记录程序未完成会话就停止了（崩溃、被终止、断电或磁盘已满）；此前已提交的内容全部保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>being recorded now: the session is not finished yet</source>
        <translation>正在记录：会话尚未完成</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (after %2 s)</source>
        <translation>%1（%2 s 后）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the session file could not be written after %1 s (%2)</source>
        <translation>%1 s 后无法写入会话文件（%2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no data for %1 s from %2 (after %3 s)</source>
        <translation>%2 已 %1 s 没有数据（%3 s 后）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the session file could not be written at the end of the run (%1)</source>
        <translation>运行结束时无法写入会话文件（%1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>test point %1: %2</source>
        <translation>测试点 %1：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table position of axis %1 must be within +-%2 deg, got %3 deg</source>
        <translation>%1 轴的转台位置须在 ±%2° 以内，当前为 %3°</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a static segment has no frequency, amplitude or start phase (got %1 Hz, %2 deg, %3 deg); leave them out</source>
        <translation>静态段没有频率、幅值或起始相位（当前为 %1 Hz、%2°、%3°）；请去掉它们</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a static segment needs a duration &gt; 0 s, got %1</source>
        <translation>静态段的时长须 &gt; 0 s，当前为 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frequency must be &gt; 0 Hz, got %1</source>
        <translation>频率须 &gt; 0 Hz，当前为 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frequency %1 Hz is beyond the table limit of %2 Hz</source>
        <translation>频率 %1 Hz 超出转台限值 %2 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>amplitude must be &gt; 0 deg, got %1</source>
        <translation>幅值须 &gt; 0°，当前为 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>amplitude %1 deg is beyond the table limit of %2 deg</source>
        <translation>幅值 %1° 超出转台限值 %2°</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>peak rate %1 deg/s exceeds the table limit of %2 deg/s; lower the frequency or amplitude</source>
        <translation>峰值角速率 %1 °/s 超出转台限值 %2 °/s；请降低频率或幅值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>peak acceleration %1 deg/s^2 exceeds the table limit of %2 deg/s^2; lower the frequency or amplitude</source>
        <translation>峰值角加速度 %1 °/s² 超出转台限值 %2 °/s²；请降低频率或幅值</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>duration must be a finite number of seconds, got %1</source>
        <translation>时长必须是有限的秒数，当前为 %1</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>duration %1 s covers %2 swing periods, under two swing periods: a delay needs at least two whole periods (%3 s)</source>
        <translation>时长 %1 s 覆盖 %2 个摆动周期，不足两个摆动周期：测量延迟至少需要两个完整周期（%3 s）</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>effect %1=%2</source>
        <translation>效应 %1=%2</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>the record covers %1 swing periods, under two swing periods: a delay needs at least two whole periods</source>
        <translation>记录覆盖 %1 个摆动周期，不足两个摆动周期：测量延迟至少需要两个完整周期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the table angle covers %1 swing periods, under two swing periods: a delay needs at least two whole periods (at %2 Hz)</source>
        <translation>转台角度覆盖 %1 个摆动周期，不足两个摆动周期：测量延迟至少需要两个完整周期（频率 %2 Hz）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>duration %1 s is over 24 h; split the test into points</source>
        <translation>时长 %1 s 超过 24 h；请将测试拆分为多个测试点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>settle time must be &gt;= 0 s, got %1</source>
        <translation>稳定时间须 &gt;= 0 s，当前为 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>start phase must be finite</source>
        <translation>起始相位须为有限值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the test plan has no test points</source>
        <translation>测试计划中没有测试点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rest time between points must be &gt;= 0 s</source>
        <translation>测试点之间的静止时间须 &gt;= 0 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the test plan has %1 test points; at most %2</source>
        <translation>测试计划有 %1 个测试点；最多 %2 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 turns the table by %2 deg with no rest time to move in; give rest_between_s &gt; 0</source>
        <translation>%1 需将转台转动 %2°，但没有可用于移动的静止时间；请设置 rest_between_s &gt; 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the move to test point %1</source>
        <translation>移动到测试点 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the return to zero after the last point</source>
        <translation>最后一个测试点之后的回零</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2 deg in %3 s) exceeds the table&apos;s rate or acceleration limit; give rest_between_s &gt;= %4 s</source>
        <translation>%1（%3 s 内转动 %2°）超出转台的角速率或角加速度限值；请设置 rest_between_s &gt;= %4 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the test plan lasts %1 h in all; at most %2 h (every sample is held in memory): split it into several sessions</source>
        <translation>测试计划总时长 %1 h；最多 %2 h（所有样本都保存在内存中）：请拆分为多个会话</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (no delay)</source>
        <translation>%1（无延迟）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no test point gave a delay</source>
        <translation>没有测试点给出延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the delay or its uncertainty is not a finite number</source>
        <translation>延迟或其不确定度不是有限数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>every test point passed its validity checks and its IMU delay + %1σ is below the %2 ms limit</source>
        <translation>每个测试点都通过了有效性检查，其 IMU 延迟 + %1σ 低于 %2 ms 限值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU delay %1 ± %2 ms; + %3σ = %4 ms &lt; %5 ms limit (margin %6 ms)</source>
        <translation>IMU 延迟 %1 ± %2 ms；+ %3σ = %4 ms &lt; %5 ms 限值（余量 %6 ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU delay %1 ± %2 ms; + %3σ = %4 ms ≥ %5 ms limit (over by %6 ms)</source>
        <translation>IMU 延迟 %1 ± %2 ms；+ %3σ = %4 ms ≥ %5 ms 限值（超出 %6 ms）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>decision rule: PASS when IMU delay + k·σ &lt; limit (k = %1, one-sided guarded acceptance, ISO/IEC 17025:2017 §7.8.6 / ILAC-G8:09/2019); FAIL otherwise; INVALID when a validity check fails; maximum probability of false accept 1 − Φ(k) = %2 (a delay measured just at the acceptance boundary, with a Gaussian error of the stated σ); limit %3 ms</source>
        <translation>判定规则：IMU 延迟 + k·σ &lt; 限值时合格（k = %1，单侧保护带验收，ISO/IEC 17025:2017 §7.8.6 / ILAC-G8:09/2019）；否则不合格；有效性检查未通过时无效；最大误接受概率 1 − Φ(k) = %2（恰好在验收边界上测得的延迟，误差为所给 σ 的高斯分布）；限值 %3 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>guard band %1σ = %2 ms; probability that the true delay is at or above the limit: %3</source>
        <translation>保护带 %1σ = %2 ms；真实延迟达到或超过限值的概率：%3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no false-accept probability: the delay is refused (INVALID)</source>
        <translation>不给出误接受概率：该延迟被拒绝（无效）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no false-accept probability: the run stopped before its plan ended (INCOMPLETE)</source>
        <translation>不给出误接受概率：运行在计划结束前停止（不完整）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not stored: the rule of that version, k = %1</source>
        <translation>未保存：该版本的规则，k = %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro turns with the table (gyro/table ratio %1)</source>
        <translation>陀螺与转台同向转动（陀螺/转台比 %1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro turns with the table (gyro/table ratio %1, after the stated sign -1)</source>
        <translation>陀螺与转台同向转动（陀螺/转台比 %1，已按声明的符号 −1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro&apos;s %1 axis turns against the table (gyro/table ratio %2): the axis is mounted the other way round or its sign convention differs from the table&apos;s; the delay is refused (read as a normal axis it would be a half-period lag). If the IMU is mounted so, state it (metadata bench.gyro_sign {&quot;%3&quot;: -1}, or --gyro-sign %4=-1) and analyse again</source>
        <translation>陀螺的 %1 轴与转台反向转动（陀螺/转台比 %2）：该轴装反了，或其符号约定与转台不同；延迟被拒绝（按正常轴读取会是半个周期的滞后）。如果 IMU 就是这样安装的，请声明（元数据 bench.gyro_sign {&quot;%3&quot;: -1}，或 --gyro-sign %4=-1）后重新分析</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the gyro&apos;s amplitude matches the table&apos;s (%1, within %2)</source>
        <translation>陀螺幅值与转台一致（%1，在 %2 以内）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro/table ratio %1</source>
        <translation>陀螺/转台比 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro/table ratio %1 at %2 Hz, where the fitted %3 response&apos;s own gain is %4: scale %5</source>
        <translation>%2 Hz 处陀螺/转台比 %1，拟合的%3响应在该频率自身的增益为 %4：标度 %5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro reads %1 (%2, outside %3): the pulse equivalent or the frame period is wrong. An increment is its pulse count times the pulse equivalent, or its rate times the IMU&apos;s frame period: check both (bench.pulse_equivalent_deg; for imported rates bench.gyro_frame_period_ms or import --frame-period-ms) and analyse again; the delay is refused</source>
        <translation>陀螺读数%1（%2，超出 %3）：脉冲当量或帧周期有误。增量等于脉冲数乘以脉冲当量，或速率乘以 IMU 的帧周期：请检查两者（bench.pulse_equivalent_deg；导入的速率还有 bench.gyro_frame_period_ms 或 import --frame-period-ms）后重新分析；延迟被拒绝</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro reads %1 (%2, outside %3): its scale is not the one the bench states. A pulse equivalent or frame period slightly off (rounded, or for another gyro) or a gyro outside its scale tolerance: check them and analyse again; the delay is refused. If the gyro&apos;s scale is known to be off by this much, state its tolerance (--gain-tolerance)</source>
        <translation>陀螺读数%1（%2，超出 %3）：其标度与台架声明的不符。可能是脉冲当量或帧周期略有偏差（经过舍入，或属于另一只陀螺），或陀螺超出了其标度容差：请检查后重新分析；延迟被拒绝。如果已知陀螺标度确实偏差这么大，请声明其容差（--gain-tolerance）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro reads %1 (%2, outside %3): its scale is not the one the bench states. A pulse equivalent or frame period slightly off (rounded, or for another gyro) or a gyro outside its scale tolerance: check them and analyse again; the delay is refused. If the gyro&apos;s own dynamics lower its gain at %4 Hz, measure its frequency response (run --preset response): the check takes out the dynamics fitted there. If the gyro&apos;s scale is known to be off by this much, state its tolerance (--gain-tolerance)</source>
        <translation>陀螺读数%1（%2，超出 %3）：其标度与台架声明的不符。可能是脉冲当量或帧周期略有偏差（经过舍入，或属于另一只陀螺），或陀螺超出了其标度容差：请检查后重新分析；延迟被拒绝。如果陀螺自身的动态特性在 %4 Hz 处降低了其增益，请测量其频率响应（run --preset response）：本检查会扣除在那里拟合出的动态特性。如果已知陀螺标度确实偏差这么大，请声明其容差（--gain-tolerance）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1× the table</source>
        <translation>为转台的 %1 倍</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1/%1 of the table</source>
        <translation>为转台的 1/%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 % more than the table</source>
        <translation>比转台多 %1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 % less than the table</source>
        <translation>比转台少 %1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not judged: the gyro/table ratio is not a finite number</source>
        <translation>未判定：陀螺/转台比不是有限数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>test point %1: IMU delay %2 ms stored, %3 ms by this version&apos;s analysis</source>
        <translation>测试点 %1：已保存的 IMU 延迟为 %2 ms，本版本的分析为 %3 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>test point %1: %2 stored, %3 by this version&apos;s analysis</source>
        <translation>测试点 %1：已保存为 %2，本版本的分析为 %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pass</source>
        <translation>通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fail</source>
        <translation>不通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid</source>
        <translation>无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>test point %1: the stored result has no delay for it; this version&apos;s analysis gives one</source>
        <translation>测试点 %1：已保存的结果中没有其延迟；本版本的分析给出了延迟</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the stored result has no delay for this test point</source>
        <translation>已保存的结果没有此测试点的延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>test point %1: the stored result has a delay; this version&apos;s analysis gives none</source>
        <translation>测试点 %1：已保存的结果中有其延迟；本版本的分析未给出延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro&apos;s %1 axis turns against the table (gyro/table ratio %2 after the stated sign -1): the axis is mounted the other way round or its sign convention differs from the table&apos;s; the delay is refused (read as a normal axis it would be a half-period lag). Check the stated sign: without it the gyro turns with the table</source>
        <translation>陀螺的 %1 轴与转台反向转动（按声明的符号 −1 后陀螺/转台比 %2）：该轴装反了，或其符号约定与转台不同；延迟被拒绝（按正常轴读取会是半个周期的滞后）。请检查声明的符号：不加它陀螺与转台同向转动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a steady sinusoid: smooth table residual %1, harmonics %2, amplitude change %3, smooth gyro residual %4 of the amplitude</source>
        <translation>稳定的正弦摆动：转台残差平滑部分 %1，谐波 %2，幅值变化 %3，陀螺残差平滑部分 %4（相对幅值）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a steady sinusoid: smooth table residual %1, harmonics %2, amplitude change %3 of the amplitude</source>
        <translation>稳定的正弦摆动：转台残差平滑部分 %1，谐波 %2，幅值变化 %3（相对幅值）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not a steady sinusoid: %1. The sine fits are biased by such a swing (the noise figures then describe the misfit, not noise); the delay is refused. Check the table&apos;s servo and amplitude, and record a steady swing</source>
        <translation>不是稳定的正弦摆动：%1。这样的摆动会使正弦拟合有偏（噪声数值描述的是失配而非噪声）；延迟被拒绝。请检查转台伺服和幅值，并记录稳定的摆动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not a steady sinusoid: %1. The sine fits are biased by such a swing (the noise figures then describe the misfit, not noise); the delay is refused. Check the table&apos;s servo and amplitude, and record a steady swing. A damped sinusoid fits the table (decay time %2 s, residual %3 of the amplitude): its lag is %4 ± %5 ms, if the decay is the table&apos;s true motion</source>
        <translation>不是稳定的正弦摆动：%1。这样的摆动会使正弦拟合有偏（噪声数值描述的是失配而非噪声）；延迟被拒绝。请检查转台伺服和幅值，并记录稳定的摆动。阻尼正弦与转台相符（衰减时间 %2 s，残差为幅值的 %3）：如果衰减是转台的真实运动，其滞后为 %4 ± %5 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the table&apos;s residual has a smooth part of %1 of the amplitude (limit %2)</source>
        <translation>转台残差的平滑部分为幅值的 %1（限值 %2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>harmonics 2-5 reach %1 of the amplitude (limit %2)</source>
        <translation>2–5 次谐波达到幅值的 %1（限值 %2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the amplitude decays by %1 over the record (limit %2)</source>
        <translation>幅值在记录期间衰减 %1（限值 %2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the amplitude grows by %1 over the record (limit %2)</source>
        <translation>幅值在记录期间增长 %1（限值 %2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro angle&apos;s residual has a smooth part of %1 of its amplitude (limit %2)</source>
        <translation>陀螺角度残差的平滑部分为其幅值的 %1（限值 %2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per-period lag drifts %1 ± %2 ppm (%3 σ)</source>
        <translation>逐周期滞后漂移 %1 ± %2 ppm（%3 σ）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>periods differ by %1 ± %2 ppm (%3 σ)</source>
        <translation>周期相差 %1 ± %2 ppm（%3 σ）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (information)</source>
        <translation>%1（仅供参考）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not judged: the swing is not a steady sinusoid (steady_sine), which moves the fitted periods and the per-period lags; %1</source>
        <translation>未判定：摆动不是稳定的正弦（steady_sine），这会移动拟合周期和逐周期滞后；%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table and gyro stamps keep one rate: %1</source>
        <translation>转台与陀螺时间戳速率一致：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro&apos;s time stamps run %1 ppm fast against the table&apos;s (%2): the two streams are not stamped on one clock at one rate, so their phase difference is not a delay. Stamp both with the sampling board&apos;s common counter (or correct the clock rate) and record again</source>
        <translation>陀螺时间戳比转台的快 %1 ppm（%2）：两路数据不是用同一时钟、同一速率打的时间戳，它们的相位差不是延迟。请用采样板的公共计数器给两者打时间戳（或校正时钟速率）后重新记录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro&apos;s time stamps run %1 ppm slow against the table&apos;s (%2): the two streams are not stamped on one clock at one rate, so their phase difference is not a delay. Stamp both with the sampling board&apos;s common counter (or correct the clock rate) and record again</source>
        <translation>陀螺时间戳比转台的慢 %1 ppm（%2）：两路数据不是用同一时钟、同一速率打的时间戳，它们的相位差不是延迟。请用采样板的公共计数器给两者打时间戳（或校正时钟速率）后重新记录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the IMU delay is negative (%1 ± %2 ms): the gyro would report rotation before it happened. A stamping, sign or clock problem: check the table read delay constant, that both streams share one clock, and the gyro axis&apos; sign</source>
        <translation>IMU 延迟为负（%1 ± %2 ms）：陀螺会在转动发生之前报告转动。这是时间戳、符号或时钟问题：请检查转台读数延迟常数、两路数据是否共用一个时钟，以及陀螺轴的符号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the IMU delay is causal (%1 ms)</source>
        <translation>IMU 延迟符合因果（%1 ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;%1&apos; is empty (0 bytes), not a fogbench session; it was never written</source>
        <translation>“%1”为空（0 字节），不是 fogbench 会话；它从未被写入</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;%1&apos; is not a fogbench session (not an SQLite database)</source>
        <translation>“%1”不是 fogbench 会话（不是 SQLite 数据库）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;%1&apos; is not a fogbench session</source>
        <translation>“%1”不是 fogbench 会话</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;%1&apos; is a folder, not a fogbench session file</source>
        <translation>“%1”是文件夹，不是 fogbench 会话文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot open session &apos;%1&apos;: no such file; check the path</source>
        <translation>无法打开会话“%1”：文件不存在；请检查路径</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the stream does not state its gyro pulse equivalent (degrees per pulse): give --pulse-equivalent-deg or set it in the bench constants</source>
        <translation>数据流未给出陀螺脉冲当量（每个脉冲的度数）：请用 --pulse-equivalent-deg 给出，或在测试台常数中设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>session &apos;%1&apos;: the stream does not state its gyro pulse equivalent (degrees per pulse): give --pulse-equivalent-deg or set it in the bench constants</source>
        <translation>会话“%1”：数据流未给出陀螺脉冲当量（每个脉冲的度数）：请用 --pulse-equivalent-deg 给出，或在测试台常数中设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;%1&apos; is truncated: it holds %2 of its %3 bytes; copy it again from the original or restore a backup</source>
        <translation>“%1”被截断：只有 %3 字节中的 %2 字节；请从原件重新复制或从备份恢复</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;%1&apos; is truncated: it holds %2 of its %3 bytes; copy it again from the original or restore a backup (its -wal does not hold the missing pages)</source>
        <translation>“%1”被截断：只有 %3 字节中的 %2 字节；请从原件重新复制或从备份恢复（其 -wal 文件中没有缺失的页）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;%1&apos; is an SQLite database but not a fogbench session (application_id %2)</source>
        <translation>“%1”是 SQLite 数据库，但不是 fogbench 会话（application_id %2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;%1&apos; is a fogbench session whose SQLite header (its first 100 bytes) is damaged; it is not analysed as a raw stream. Restore it from a backup, or repair a copy: printf &apos;SQLite format 3\0&apos; | dd of=COPY.fbs conv=notrunc (when only the header&apos;s first bytes were hit, the copy opens again)</source>
        <translation>“%1”是 fogbench 会话，但其 SQLite 文件头（前 100 字节）已损坏；不会把它当作原始数据流分析。请从备份恢复，或修复一份副本：printf &apos;SQLite format 3\0&apos; | dd of=COPY.fbs conv=notrunc（只有文件头的前几个字节受损时，副本即可重新打开）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;%1&apos; is a fogbench session whose first page (the SQLite header and the list of its tables, 4 KiB) is damaged; it is not analysed as a raw stream (the stream inside is cut into database pages). Restore it from a backup</source>
        <translation>“%1”是首页（SQLite 文件头及其表目录，4 KiB）已损坏的 fogbench 会话；不会作为原始数据流分析（其中的数据流被切分在数据库页中）。请从备份恢复</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is %2, not %3: only regular files are read (a pipe or a device may never end); copy the data into a file first</source>
        <translation>%1 是%2，不是%3：只读取普通文件（管道或设备可能永无结束）；请先将数据复制到文件中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (a link to %2) is %3, not %4: only regular files are read (a pipe or a device may never end); copy the data into a file first</source>
        <translation>%1（指向 %2 的链接）是%3，不是%4：只读取普通文件（管道或设备可能永无结束）；请先将数据复制到文件中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a FIFO (named pipe)</source>
        <translation>FIFO（命名管道）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a device</source>
        <translation>设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a fogbench session file</source>
        <translation>fogbench 会话文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a raw sampling-board stream</source>
        <translation>采样板原始数据流</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a plan file</source>
        <translation>计划文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 holds %2 bytes, more than the %3 that %4 may hold (docs/reliability.md): split the recording</source>
        <translation>%1 有 %2 字节，超过%4允许的 %3（docs/reliability.md）：请拆分记录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fits gave no finite %1 (%2): the data hold values the sine model cannot fit; check the recording&apos;s units and values</source>
        <translation>拟合未得到有限的%1（%2）：数据中有正弦模型无法拟合的数值；请检查记录的单位和数值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the run reached its memory budget of %1 table and IMU samples after %2 s; everything recorded is kept</source>
        <translation>运行在 %2 s 后达到其内存预算（%1 个转台和 IMU 样本）；已记录的全部数据均已保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no verdict: %1, not a finite number, so real and simulated data cannot be compared</source>
        <translation>无结论：%1 不是有限数值，因此无法比较实测数据与仿真数据</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>undetermined</source>
        <translation>无法判定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>static segment %1: the %2 gyro&apos;s %3 increments are all %4 deg: no noise to analyse (a dead or disconnected axis, or a file of constants)</source>
        <translation>静态段 %1：%2 陀螺的 %3 个增量全为 %4°：没有可分析的噪声（轴失效或未连接，或文件中为常数）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Markov (correlated) rate</source>
        <translation>马尔可夫（相关）角速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the replay cannot reach the measured lag exactly</source>
        <translation>回放无法精确达到测得的滞后</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heading %1 +- %2 deg, from the Earth rate the gyros see as the table turns</source>
        <translation>航向 %1 ± %2 deg，由转台转动时陀螺感受到的地球自转角速度求得</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heading %1 +- %2 deg, from the Earth rate the gyros see as the table turns; %3 is taken &gt;= 0: the plan&apos;s swings do not show its sign</source>
        <translation>航向 %1 ± %2 deg，由转台转动时陀螺感受到的地球自转角速度求得；%3 取 &gt;= 0：计划中的摆动显示不出它的符号</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>left out: %1</source>
        <translation>未计入：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not stated</source>
        <translation>未声明</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>north-east-down (x north, y east, z down)</source>
        <translation>北东地（x 北，y 东，z 下）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>east-north-up (x east, y north, z up)</source>
        <translation>东北天（x 东，y 北，z 上）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>forward-right-down (x forward, y right, z down)</source>
        <translation>前右下（x 前，y 右，z 下）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>right-forward-up (x right, y forward, z up)</source>
        <translation>右前上（x 右，y 前，z 上）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, forward at %2 deg from north</source>
        <translation>%1，前向轴方位 %2 deg（自北起）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>up</source>
        <translation>向上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>down</source>
        <translation>向下</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the IMU&apos;s frame was not checked: the plan gives too few gyro trend and cross-axis cells</source>
        <translation>未检验 IMU 坐标系：计划给出的陀螺趋势与交叉轴单元太少</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the IMU&apos;s frame was not checked: the plan&apos;s swings do not turn the Earth rate between the gyros</source>
        <translation>未检验 IMU 坐标系：计划中的摆动不会使地球自转角速度在各陀螺之间转换</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the IMU&apos;s frame was not checked: the plan&apos;s swings do not turn the vertical Earth rate between the gyros</source>
        <translation>未检验 IMU 坐标系：计划中的摆动不会使地球自转角速度的垂直分量在各陀螺之间转换</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the stated frame is used</source>
        <translation>采用所声明的坐标系</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>z down is assumed: state the IMU&apos;s frame</source>
        <translation>假定 z 轴向下：请声明 IMU 坐标系</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the data cannot tell the IMU&apos;s z axis up from down (vertical Earth rate %1 +- %2 of the z-%3 frame&apos;s)</source>
        <translation>数据无法分辨 IMU 的 z 轴向上还是向下（地球自转垂直分量为 z 轴%3坐标系的 %1 ± %2 倍）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the data show the IMU&apos;s z axis %1 (vertical Earth rate %2 +- %3 of the z-%4 frame&apos;s)</source>
        <translation>数据表明 IMU 的 z 轴%1（地球自转垂直分量为 z 轴%4坐标系的 %2 ± %3 倍）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the data show the IMU&apos;s z axis %1 (vertical Earth rate %2 +- %3 of the z-%4 frame&apos;s), as the bench constants state</source>
        <translation>数据表明 IMU 的 z 轴%1（地球自转垂直分量为 z 轴%4坐标系的 %2 ± %3 倍），与台架常数的声明一致</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bench constants state %1: the replays use the frame the data show</source>
        <translation>台架常数声明为%1：回放采用数据所表明的坐标系</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bench constants do not state the IMU&apos;s frame, so the replays use the one found: state it in the bench constants (a latitude of the wrong sign looks the same)</source>
        <translation>台架常数未声明 IMU 坐标系，回放采用由数据判定的坐标系：请在台架常数中声明（纬度符号错误时看起来相同）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a latitude of the wrong sign looks the same</source>
        <translation>纬度符号错误时看起来相同</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a latitude of the wrong sign (the other hemisphere) looks the same: check it too</source>
        <translation>纬度符号错误（另一半球）时看起来相同：也请检查纬度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the heading the data show, %1 deg, is %2 deg from the stated frame&apos;s (%3 deg for x): check the bench&apos;s heading</source>
        <translation>数据表明的方位角 %1 deg 与所声明坐标系的方位角（x 轴 %3 deg）相差 %2 deg：请检查台架的方位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the replays use the one found</source>
        <translation>回放采用由数据判定的方位角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the IMU&apos;s frame contradicts the data (no effect named)</source>
        <translation>IMU 坐标系与数据矛盾（不指认任何效应）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the data show the IMU&apos;s z axis %1</source>
        <translation>数据表明 IMU 的 z 轴%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bench constants state %1 (%2). Correct the IMU frame in the bench constants (or the IMU&apos;s mounting) and diagnose again</source>
        <translation>台架常数声明为%1（%2）。请更正台架常数中的 IMU 坐标系（或 IMU 的安装）后重新诊断</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no effect is named. Replayed in the frame the data show, the verdict would be: %1</source>
        <translation>不指认任何效应。在数据所表明的坐标系中回放，结论将是：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 position is not a number</source>
        <translation>%1 位置不是数值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 position %2 deg is beyond the table&apos;s +-%3 deg</source>
        <translation>%1 位置 %2 deg 超出转台的 ±%3 deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the table was not moved</source>
        <translation>转台未运动</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Operation not permitted</source>
        <translation>操作不允许</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No such file or directory</source>
        <translation>没有那个文件或目录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Interrupted system call</source>
        <translation>系统调用被中断</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Input/output error</source>
        <translation>输入/输出错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No such device or address</source>
        <translation>没有那个设备或地址</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bad file descriptor</source>
        <translation>文件描述符错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resource temporarily unavailable</source>
        <translation>资源暂时不可用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Permission denied</source>
        <translation>权限不够</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device or resource busy</source>
        <translation>设备或资源忙</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File exists</source>
        <translation>文件已存在</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No such device</source>
        <translation>没有那个设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not a directory</source>
        <translation>不是目录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Is a directory</source>
        <translation>是一个目录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invalid argument</source>
        <translation>无效的参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Too many open files in system</source>
        <translation>系统中打开的文件过多</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Too many open files</source>
        <translation>打开的文件过多</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inappropriate ioctl for device</source>
        <translation>对设备不适当的 ioctl 操作</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File too large</source>
        <translation>文件过大</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No space left on device</source>
        <translation>设备上没有空间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read-only file system</source>
        <translation>只读文件系统</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Broken pipe</source>
        <translation>断开的管道</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File name too long</source>
        <translation>文件名过长</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Too many levels of symbolic links</source>
        <translation>符号链接的层数过多</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disk quota exceeded</source>
        <translation>超出磁盘限额</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connection refused</source>
        <translation>拒绝连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connection reset by peer</source>
        <translation>连接被对方重置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connection timed out</source>
        <translation>连接超时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No route to host</source>
        <translation>没有到主机的路由</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Network is unreachable</source>
        <translation>网络不可达</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Address already in use</source>
        <translation>地址已在使用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Transport endpoint is not connected</source>
        <translation>传输端点尚未连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Text file busy</source>
        <translation>文本文件忙</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cannot allocate memory</source>
        <translation>无法分配内存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot create session &apos;%1&apos;: %2; check the folder exists and is writable</source>
        <translation>无法创建会话“%1”：%2；请检查文件夹是否存在且可写</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bias instability %1 deg/h over %2 s assumed (the simulator&apos;s default): a bias drift or step within such a wander is not resolved; state the IMU&apos;s own (its static noise test) for a sharper test of the gyro trends</source>
        <translation>假定零偏不稳定性 %1 deg/h、相关时间 %2 s（仿真器默认值）：在这种漂移范围内的零偏漂移或阶跃无法分辨；给出该 IMU 自身的值（其静态噪声测试）可更严格地检验陀螺趋势</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ran on %1 of the %2 threads asked for, to stay within the %3 MB memory limit</source>
        <translation>为不超过 %3 MB 的内存限制，只用了所要求的 %2 个线程中的 %1 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the Ceres fit on the forward model failed (%1); linear fit kept</source>
        <translation>正向模型上的 Ceres 拟合失败（%1）；保留线性拟合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fogbench delay report</source>
        <translation>fogbench 延迟报告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>source: session %1 (%2)</source>
        <translation>来源：会话 %1（%2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>source: %1</source>
        <translation>来源：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>verdict: %1</source>
        <translation>结论：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>verdict: %1 (delay refused)</source>
        <translation>结论：%1（延迟被拒绝）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PASS</source>
        <translation>通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FAIL</source>
        <translation>不通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>INVALID</source>
        <translation>无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>INCOMPLETE</source>
        <translation>未完成</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stored verdict: %1, against the stored limit of %2 ms</source>
        <translation>已保存的判定：%1，依据保存的限值 %2 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stored verdict: %1 (the data recorded give %2), against the stored limit of %3 ms</source>
        <translation>已保存的判定：%1（已记录的数据给出 %2），依据保存的限值 %3 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This version&apos;s analysis of the same data with the same settings differs from the stored result:</source>
        <translation>本版本以相同设置对相同数据的分析与已保存的结果不同：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This version&apos;s analysis with the stored result&apos;s settings (plots and fits):</source>
        <translation>本版本以已保存结果的设置所做的分析（曲线与拟合）：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>INCOMPLETE RUN: %1</source>
        <translation>运行未完成：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stream: %1 table, %2 IMU, %3 status frames; %4 checksum failures, %5 lost, %6 duplicated, %7 bytes skipped</source>
        <translation>数据流：转台帧 %1，IMU 帧 %2，状态帧 %3；校验失败 %4，丢失 %5，重复 %6，跳过字节 %7</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bench constants: table read delay %1 ± %2 ms, board delay %3 ± %4 ms</source>
        <translation>台架常数：转台读数延迟 %1 ± %2 ms，板延迟 %3 ± %4 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro signs: %1 (-1: the gyro axis counts against the table&apos;s); IMU frame: %2</source>
        <translation>陀螺符号：%1（−1：陀螺轴与转台轴反向计数）；IMU 坐标系：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test point %1: %2 axis, %3 Hz / %4 deg, %5 s (%6 periods)</source>
        <translation>测试点 %1：%2 轴，%3 Hz / %4 deg，%5 s（%6 个周期）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fits (angle = A sin(2 pi (t - t0) / T); t0 is the phase):</source>
        <translation>拟合（角度 = A sin(2π(t − t0)/T)；t0 为相位）：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 period %2 (nominal) ms phase %3 ± %4 ms amplitude %5 deg</source>
        <translation>%1&#x3000;周期 %2（标称）ms&#x3000;相位 %3 ± %4 ms&#x3000;幅值 %5 deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 period %2 ± %3 ms phase %4 ± %5 ms amplitude %6 deg</source>
        <translation>%1&#x3000;周期 %2 ± %3 ms&#x3000;相位 %4 ± %5 ms&#x3000;幅值 %6 deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table 3-parameter</source>
        <translation>转台 三参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro 3-parameter</source>
        <translation>陀螺 三参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>table 4-parameter</source>
        <translation>转台 四参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro 4-parameter</source>
        <translation>陀螺 四参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>joint fit: frequency %1 Hz, gyro/table amplitude %2, trend %3 deg/s (%4 deg/h), chi2/dof %5</source>
        <translation>联合拟合：频率 %1 Hz，陀螺/转台幅值比 %2，趋势 %3 deg/s（%4 deg/h），chi2/dof %5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>delay:</source>
        <translation>延迟：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>measured lag (gyro behind table) %1 ± %2 ms (CRLB %3 ms, std/CRLB %4)</source>
        <translation>测得滞后（陀螺落后于转台）&#x3000;%1 ± %2 ms（CRLB %3 ms，标准差/CRLB %4）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uncertainty from %1 (fit alone %2 ms, per-period scatter %3 ms)</source>
        <translation>不确定度取自%1（仅拟合 %2 ms，逐周期离散 %3 ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fit, with errors that repeat every period</source>
        <translation>拟合，含每个周期重复的误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per-period scatter, with errors that repeat every period</source>
        <translation>逐周期离散，含每个周期重复的误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fit, less the errors that cancel between periods</source>
        <translation>拟合，扣除周期之间相互抵消的误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per-period scatter, less the errors that cancel between periods</source>
        <translation>逐周期离散，扣除周期之间相互抵消的误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per-period scatter</source>
        <translation>逐周期离散</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fit, random walk at its upper bound (fewer than 5 periods to check it)</source>
        <translation>拟合，随机游走取其上限（不足 5 个周期无法检验）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>+ table read delay %1 ms</source>
        <translation>+ 转台读数延迟&#x3000;&#x3000;&#x3000;%1 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>= IMU delay %1 ± %2 ms</source>
        <translation>= IMU 延迟&#x3000;&#x3000;&#x3000;&#x3000;&#x3000;%1 ± %2 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>- processing board delay %1 ms</source>
        <translation>− 处理板延迟&#x3000;&#x3000;&#x3000;&#x3000;%1 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>= gyro&apos;s own delay %1 ± %2 ms</source>
        <translation>= 陀螺自身延迟&#x3000;&#x3000;&#x3000;%1 ± %2 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>simulator truth: lag %1 ms (error %2 ms = %3 std)</source>
        <translation>仿真真值：滞后 %1 ms（误差 %2 ms = %3 倍标准差）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per-period delay: %1 periods, mean %2 ms, scatter %3 ms</source>
        <translation>逐周期延迟：%1 个周期，均值 %2 ms，离散 %3 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>noise: encoder %1 deg, pulse output %2 deg, angle random walk %3 deg/sqrt(h) (near the swing frequency %4)</source>
        <translation>噪声：编码器 %1 deg，脉冲输出 %2 deg，角度随机游走 %3 deg/sqrt(h)（摆动频率附近 %4）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lost IMU frames: %1</source>
        <translation>丢失的 IMU 帧：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>affected: %1 table and %2 IMU frames lost, %3 duplicated, %4 checksum failures, %5 bytes skipped; data cover %6 of %7 s (%8 %), longest gap %9 ms</source>
        <translation>受影响：丢失转台帧 %1、IMU 帧 %2，重复 %3，校验失败 %4，跳过字节 %5；数据覆盖 %7 s 中的 %6 s（%8 %），最长缺口 %9 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checks:</source>
        <translation>检查：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ok %1: %2</source>
        <translation>通过&#x3000;%1：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FAILED %1: %2</source>
        <translation>未通过&#x3000;%1：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>n/a %1: %2</source>
        <translation>未判定&#x3000;%1：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test point %1: static segment, %2 axis, %3 s at rest: no delay to measure (gyro noise: fogbench-cli noise)</source>
        <translation>测试点 %1：静止段，%2 轴，静止 %3 s：没有可测的延迟（陀螺噪声：fogbench-cli noise）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no delay from %1</source>
        <translation>%1 没有给出延迟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delay against frequency, %1 axis (%2 frequencies): weighted lag %3 ± %4 ms, chi2 %5 on %6 dof, p = %7: %8</source>
        <translation>延迟随频率，%1 轴（%2 个频率）：加权滞后 %3 ± %4 ms，chi2 %5（%6 个自由度），p = %7：%8</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>consistent with a pure delay</source>
        <translation>与纯延迟一致</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NOT a pure delay (frequency-dependent: lag, filtering or dynamics)</source>
        <translation>不是纯延迟（随频率变化：滞后、滤波或动态特性）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the table swung at %1 Hz, not the planned %2 Hz; fitting from the measured frequency</source>
        <translation>转台以 %1 Hz 摆动，而非计划的 %2 Hz；按测得的频率拟合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the per-period lags scatter %1 ms, more than the fit&apos;s noise model implies; the uncertainty rests on their scatter (%2 ms instead of %3 ms)</source>
        <translation>逐周期滞后的离散为 %1 ms，大于拟合噪声模型所预期的；不确定度取自其离散（%2 ms，而非 %3 ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the per-period lags scatter %1 ms, less than the fit&apos;s noise model implies; the uncertainty rests on their scatter (%2 ms instead of %3 ms)</source>
        <translation>逐周期滞后的离散为 %1 ms，小于拟合噪声模型所预期的；不确定度取自其离散（%2 ms，而非 %3 ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 IMU frames were lost; their increments are missing</source>
        <translation>丢失了 %1 个 IMU 帧；其增量缺失</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 table frames were lost; the data cover %2 of %3 s (longest gap %4 ms)</source>
        <translation>丢失了 %1 个转台帧；数据覆盖 %3 s 中的 %2 s（最长缺口 %4 ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the residuals do not match the noise model (chi^2/dof = %1); an unmodelled effect may be present</source>
        <translation>残差与噪声模型不符（chi^2/dof = %1）；可能存在未建模的效应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the table swung %1 deg, not the planned %2 deg</source>
        <translation>转台摆幅为 %1 deg，而非计划的 %2 deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the gyro&apos;s own delay is negative: the processing board delay (%1 ms) is larger than the IMU delay; check that constant</source>
        <translation>陀螺自身延迟为负：处理板延迟（%1 ms）大于 IMU 延迟；请检查该常数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis_sign</source>
        <translation>轴向符号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steady_sine</source>
        <translation>稳定正弦</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>clock_rate</source>
        <translation>时钟速率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>causal</source>
        <translation>因果性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>uncertainty_below_bound</source>
        <translation>不确定度低于下界</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>σ %1 ms is %2 of the Cramér–Rao bound %3 ms (%4, %5 degrees of freedom; at least %6 expected)</source>
        <translation>σ %1 ms 为克拉美–罗界 %3 ms 的 %2 倍（%4，自由度 %5；应至少为 %6）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>σ %1 ms is %2 of the Cramér–Rao bound %3 ms; before the errors that cancel between periods, which the bound&apos;s white noise does not see, %4 ms, %5 of it (%6, %7 degrees of freedom; at least %8 expected)</source>
        <translation>σ %1 ms 为克拉美–罗界 %3 ms 的 %2 倍；扣除周期之间相互抵消的误差（该界的白噪声模型看不到）之前为 %4 ms，即该界的 %5 倍（%6，自由度 %7；应至少为 %8）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the stated uncertainty is below what the noise allows: %1. No estimate of the lag scatters less than the bound; the σ is understated and the delay is not vouched for. Record more periods, or check the noise model (docs/method.md)</source>
        <translation>给出的不确定度低于噪声所允许的下限：%1。任何滞后估计的离散都不会小于该下界；σ 被低估，延迟无法担保。请记录更多周期，或检查噪声模型（docs/method.md）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not judged: the Cramér–Rao bound of this session&apos;s noise is not known</source>
        <translation>未判定：本次会话噪声的克拉美–罗界未知</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fit</source>
        <translation>拟合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>measured lag (gyro behind table) %1 ± %2 ms (CRLB %3 ms, std/CRLB %4: BELOW THE BOUND, the σ is understated (uncertainty_below_bound))</source>
        <translation>测得滞后（陀螺落后于转台）&#x3000;%1 ± %2 ms（CRLB %3 ms，标准差/CRLB %4：低于下界，σ 被低估（uncertainty_below_bound））</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, fogbench %2</source>
        <translation>%1，fogbench %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the -3 dB bandwidth %1 Hz lies beyond the highest point (%2 Hz): an extrapolation of the model</source>
        <translation>−3 dB 带宽 %1 Hz 超出最高测试点（%2 Hz）：为模型的外推</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 and %2 correlate at %3: the points barely separate them (the low-frequency delay %4 ± %5 ms is better determined than either)</source>
        <translation>%1 与 %2 的相关系数为 %3：这些点几乎无法将二者区分（低频延迟 %4 ± %5 ms 比二者中任何一个都确定得更好）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 = %2 ± %3 is not distinguished from 0 by these points</source>
        <translation>%1 = %2 ± %3：这些点无法将其与 0 区分</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2 parameters need more than %3 values, %4 points give %5</source>
        <translation>%1：%2 个参数需要多于 %3 个数值，%4 个点只给出 %5 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: no fit from any of its %2 starting points (%3); the points may not hold such a filter</source>
        <translation>%1：%2 个初值均未得到拟合（%3）；这些点可能不含此类滤波器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fit did not converge in %1 iterations</source>
        <translation>拟合在 %1 次迭代内未收敛</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: its best fit has 1/wn^2 = %2 ms^2, not above 0: the points hold no resonance (the first-order lag, T = %3 ms, is its limit)</source>
        <translation>%1：最佳拟合的 1/ωn² = %2 ms²，不大于 0：这些点不含谐振（其极限为一阶滞后，T = %3 ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: its best fit has 1/wn^2 = %2 ms^2, not above 0: the points hold no resonance (a magnitude droop without a filter&apos;s phase, as an average over about %3 ms would give)</source>
        <translation>%1：最佳拟合的 1/ωn² = %2 ms²，不大于 0：这些点不含谐振（幅值下降而无滤波器的相位，如同约 %3 ms 的平均所致）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>AIC prefers it to %1 by %2, but it lowers chi^2 by %3 only (1 more parameter claimed at %4, 3 sigma): %5 is chosen</source>
        <translation>AIC 比%1更倾向于它（差 %2），但它只使 χ² 降低 %3（多 1 个参数须降低 %4，即 3σ）：选择%5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>AIC prefers it to %1 by %2, but it lowers chi^2 by %3 only (%4 more parameters claimed at %5, 3 sigma): %6 is chosen</source>
        <translation>AIC 比%1更倾向于它（差 %2），但它只使 χ² 降低 %3（多 %4 个参数须降低 %5，即 3σ）：选择%6</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no model fits: %1</source>
        <translation>没有模型拟合：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no model fits: none could be fitted</source>
        <translation>没有模型拟合：没有任何模型能够拟合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is not adequate: chi^2 %2 on %3 dof, p = %4 below %5</source>
        <translation>%1 拟合不充分：χ² %2，自由度 %3，p = %4 低于 %5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is not admissible: %2</source>
        <translation>%1 不可接受：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 = %2 ± %3 ms is negative beyond 3 sigma: the gyro would answer before the table moves</source>
        <translation>%1 = %2 ± %3 ms 为负且超出 3σ：陀螺将在转台运动之前响应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 = %2 ± %3 ms is negative beyond 3 sigma: a lead, not a lag</source>
        <translation>%1 = %2 ± %3 ms 为负且超出 3σ：是超前而非滞后</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the low-frequency delay %1 ± %2 ms is negative beyond 3 sigma: the gyro would answer before the table moves</source>
        <translation>低频延迟 %1 ± %2 ms 为负且超出 3σ：陀螺将在转台运动之前响应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 = %2 ± %3 ms is below -%4 ms (minus the table read delay) beyond 3 sigma: the gyro would answer before the table moves</source>
        <translation>%1 = %2 ± %3 ms 低于 -%4 ms（负的转台读数延迟）且超出 3σ：陀螺将在转台运动之前响应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the low-frequency delay %1 ± %2 ms is below -%3 ms (minus the table read delay) beyond 3 sigma: the gyro would answer before the table moves</source>
        <translation>低频延迟 %1 ± %2 ms 低于 -%3 ms（负的转台读数延迟）且超出 3σ：陀螺将在转台运动之前响应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 = %2 ± %3 sits at its bound 0 within 3 sigma: the points do not place the resonance</source>
        <translation>%1 = %2 ± %3 在 3σ 内处于其边界 0：这些点无法确定谐振</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fit ran past zeta = 0: its poles are unstable (a lead that grows to the resonance)</source>
        <translation>拟合越过了 ζ = 0：其极点不稳定（超前随频率增大直至谐振）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the pure delay</source>
        <translation>纯延迟模型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the first-order lag</source>
        <translation>一阶滞后模型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the second-order response</source>
        <translation>二阶响应模型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fit&apos;s sums are not finite numbers (a value in the data is far beyond its range)</source>
        <translation>拟合的求和不是有限数（数据中有数值远超其范围）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fit&apos;s parameters are not determined by the data</source>
        <translation>拟合参数无法由数据确定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fit&apos;s covariance is not positive</source>
        <translation>拟合的协方差不为正</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>first_order</source>
        <translation>一阶模型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>second_order</source>
        <translation>二阶模型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tau_ms</source>
        <translation>τ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T_ms</source>
        <translation>T</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fn_hz</source>
        <translation>fₙ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>zeta</source>
        <translation>ζ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>SQLite catalog %1</source>
        <translation>SQLite 目录 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PostgreSQL catalog %1</source>
        <translation>PostgreSQL 目录 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not recorded</source>
        <translation>未记录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stored</source>
        <translation>已保存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>given</source>
        <translation>给定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>units whose latest session&apos;s shown result is PASS, over units</source>
        <translation>最近一次会话显示的结果为通过的单元数，除以单元数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>units whose first session&apos;s shown result is PASS, over units</source>
        <translation>第一次会话显示的结果为通过的单元数，除以单元数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>over the vouched test points (PASS or FAIL) of shown PASS or FAIL results; INVALID and INCOMPLETE results are counted, never averaged</source>
        <translation>取自显示中的通过或不通过结果的可担保测试点（通过或不通过）；无效和不完整的结果只计数，从不参与平均</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>(limit - mean) / (3 s), one-sided: the IMU delay has an upper limit only</source>
        <translation>(限值 − 均值) / (3 s)，单侧：IMU 延迟只有上限</translation>
    </message>
</context>
</TS>
