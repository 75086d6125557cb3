# axcheck 报告用语（简体中文）。键与 en.ftl、ru.ftl 相同（测试比较键集和各消息的参数）。
# 参数名称和符号按 GB/T 17421.2-2000《机床检验通则 第2部分：数控轴线的定位精度和重复定位
# 精度的确定》第2章的术语（ISO 230-2 和 GB/T 17421.2 的检验均用之）。日期为 YYYY-MM-DD
# （GB/T 7408 的数字形式），小数点为“.”。

## Page and shared tables (style.typ)
page-of = 第 { $page } 页，共 { $total } 页
col-parameter = 参数
col-value = 数值
col-u = U（k = 2）
col-limit = 允差
col-margin = 余量
col-status = 状态
status-pass = 合格
status-fail = 不合格
status-na = 不适用
status-inconclusive = 不确定
col-inspections = 检验次数
col-latest = 最近值
col-slope = 斜率
col-reaches-limit = 达到允差
trend-flagged = 已标记
trend-method = 斜率：每年两两斜率的 Theil–Sen 中位数（对个别异常检验稳健），± 由 Sen 95 % 区间得出的标准误差；图中的带为该区间的两条斜率线，通过直线中点。“达到允差”：直线与最近允差相交之处（B̄ 取 |B̄|）。当直线在期限内达到允差、已超过允差，或在期限内显著（95 %）恶化至少允差的十分之一时，该序列被标记。

## Units
unit-um = µm
unit-mm = mm
unit-arcsec = 角秒
unit-s = s

## Verdicts
verdict-pass = 合格
verdict-fail = 不合格
verdict-noncompliant = 不符合检验规程
verdict-error = 错误
verdict-inconclusive = 不能判定
verdict-not-judged = 未判定
verdict-detail-not-judged = 未判定：未给出允差，未与任何允差比较；仅作了评定并按检验规程规则检查。
verdict-detail-pass-one = 有允差的参数在允差之内。
verdict-detail-pass-all = 全部 { $count } 个有允差的参数均在允差之内。
verdict-detail-fail = 超出允差：{ $symbols }。
verdict-detail-noncompliant = 检验不符合标准规定的检验规程（{ $rules }）：其结果不能用于验收。
verdict-detail-inconclusive = 在允差处落入测量不确定度之内（ISO 14253-1：允差 ± U）：{ $zone }。既不能证明合格，也不能证明不合格。
verdict-zone = { $symbol } = { $value } ± { $u } { $unit }，允差 { $limit } { $unit }
verdict-large-uncertainty = { $detail } 对此判定而言不确定度较大：{ $list }。

## Axis report: header
axis-report-kind = 定位精度和重复定位精度检验报告
axis-title = { $machine } — 轴线 { $axis }
purpose-inspection = { $purpose }检验
in-full-below = { $name }（全称见下）
fact-machine-in-full = 机床全称
fact-axis-in-full = 轴线全称
fact-machine = 机床
fact-machine-in-file = 文件中的机床
fact-model = 型号
fact-serial = 出厂编号
fact-type = 类型
fact-location = 地点
fact-axis = 轴线
fact-axis-in-file = 文件中的轴线
fact-axis-travel = 轴线行程
fact-measurement-travel = 测量行程
fact-measurement-file = 测量文件
fact-file-sha = 文件 SHA-256
fact-test = 检验
fact-test-of = 本轴线 { $tests } 次检验中的第 { $test } 次
fact-standard = 标准
fact-spec = 验收规范
fact-date = 检验日期
fact-inspector = 检验人员
from-measurement-file = { $value }（测量文件）
axis-kind-linear = 直线
axis-kind-rotary = 回转

## Axis report: test conditions
conditions-heading = 检验条件（GB/T 17421.2 第 7.1 条）
cond-instrument = 测量仪器
cond-instrument-position = 仪器位置
cond-equipment = 检验设备
cond-positioning-element = 定位元件
cond-nde = 名义差异膨胀修正（3.1）
cond-feed = 进给速度
cond-dwell = 各目标位置的停留时间
cond-compensation = 启用的补偿（3.2）
cond-other-axes = 其他轴线的位置（3.2）
cond-tool-offset = 刀具偏置
cond-workpiece-offset = 工件偏置
cond-warm-up = 预热（3.3）
cond-cycle = 检验循环
cond-air = 空气（开始 → 结束）
cond-pressure = 气压或油压
cond-approaches = 每个方向的趋近次数
cond-approaches-value = 在 { $targets } 个目标位置上各 n = { $n } 次
cond-read-as = 测量文件读作
cond-from-file = 取自测量文件
cond-notes = 备注
cond-not-stated = 未说明
cycle-standard = 标准检验循环（GB/T 17421.2 图 1）
cycle-step = 阶梯循环（GB/T 17421.2 附录 A）
cycle-pilgrim = 朝圣步循环（GOST 27843 图 2）
unstated-instrument-position = 测量仪器的位置
unstated-sensor-positions = 温度传感器的位置
unstated-model = 机床型号
unstated-type = 机床类型
unstated-equipment = 检验设备（制造厂、型号、编号）
unstated-expansion = 定位元件的膨胀系数
unstated-offsets = 刀具和工件偏置
unstated-material = 开始和结束时的材料温度
unstated-air = 开始和结束时的空气温度
unstated-pressure = 开始和结束时的气压和湿度
unstated-compensation = 检验时启用的补偿（3.2）
sensor-heading = 温度传感器
sensor-kind = 类型
sensor-position = 位置
sensor-start = 开始
sensor-end = 结束

## Axis report: results
results-heading = 检验结果（单位：{ $unit }）
note = 注：{ $note }
at-target = 在 i = { $i }（{ $position }）
not-applicable = 不适用
fig-bidirectional = 双向定位精度和重复定位精度（参照 GB/T 17421.2 图 2a）
fig-unidirectional = 单向定位精度和重复定位精度（参照 GB/T 17421.2 图 2b）
chart-approach = 趋近 { $arrow }
chart-mean = 平均 X̄i{ $arrow }
chart-readings = 读数 { $arrow }
chart-mean-bidirectional = 双向平均 X̄i
chart-target-position = 目标位置 Pi / { $unit }
target-position = 位置 Pi
chart-positional-deviation = 位置偏差 / { $unit }
targets-heading = 各目标位置的结果（{ $unit }，按 GB/T 17421.2 表 2 的格式）
target-direction = 方向

## Axis report: the results of the tool that wrote the file
other-tool-heading = 文件中 { $name } 的结果与 axcheck 的结果对照
other-tool-intro = 文件载有其软件计算的结果{ $state }。axcheck 按 ISO 230-2 评定同一组读数；两者之差不超过软件的修约和读数的修约所能解释的范围时，即为一致。
other-tool-state = （状态：{ $state }）
other-tool-its-result = 其结果
other-tool-as-printed = 原文
other-tool-theirs = 其值（{ $unit }）
other-tool-ours = axcheck（{ $unit }）
other-tool-difference = 差值
other-tool-agree = 一致
other-tool-differ = 不一致
other-tool-not-compared = 非 ISO 230-2 参数，未比较：{ $list }。

## Axis report: at the tool point
tool-point-heading = 刀具点处（阿贝）
tool-point-error = 检验结果无法换算到刀具点：{ $error }
tool-point-intro = 激光在光束上测量本轴线；刀具点在横向距光束 { $offsets } 处。每个读数通过本轴线的角度检验 { $rotations } 换算到该处：偏置乘以该目标位置和方向上角度的正切（HP 5528A 用户指南，附录 B），然后按实测值评定和判定。
tool-point-verdicts = 光束处判定：{ $beam }；刀具点处判定：{ $tool }
tool-point-changes = 转角改变了判定
tool-point-at-beam = 光束处（{ $unit }）
tool-point-at-tool = 刀具点处（{ $unit }）
tool-point-outcome = 刀具点处

## Axis report: uncertainty
uncertainty-heading = 测量不确定度（GUM，k = 2）
uncertainty-intro = 测量行程（{ $length }）上的不确定度评定：合成标准不确定度 u{ $c } = { $combined } { $unit }，扩展不确定度 U = 2u{ $c } = { $expanded } { $unit }。结果表中每个参数的 U 为其所跨长度上的评定，并含其自身估算值的统计。
col-contributor = 分量
col-distribution = 分布
col-share = 占比
check-model-empty = 没有可显示的模型检查。
check-model-band-key = 模拟的 95 % 区间（基本模型）
check-model-band-head = 模拟的 95 % 区间
check-model-band-head-narrow = 95 % 区间
check-model-measured = 实测
check-model-outside = 实测，检查超出
check-model-scale = 各统计量各自的刻度
check-decision-empty = 没有可显示的有允差参数。
check-decision-band-key = 允差 ± U：不能判定区（ISO 14253-1）
check-decision-band-head = 允差 − U … 允差 + U
check-decision-band-head-narrow = 允差 ± U
check-decision-value = 数值
check-decision-outside = 数值，已证明不合格
check-decision-scale = 各参数各自的刻度
check-beyond = 超出刻度
contributor-air-humidity = 空气湿度
contributor-air-pressure = 气压
contributor-air-temperature = 空气温度
contributor-calibration = 校准
contributor-dead-path = 死程
contributor-expansion-coefficient = 膨胀系数
contributor-instrument-repeatability = 仪器重复性
contributor-material-temperature = 材料温度
contributor-mean-of-n = n 次平均
contributor-misalignment = 对准误差
contributor-resolution = 分辨力
contributor-s-of-n = n 次的 S
contributor-temperature-change = 温度变化
contributor-uncorrected-expansion = 未修正的膨胀
contributor-repeatability = 重复性
contributor-optics = 光学元件
distribution-normal = 正态
distribution-rectangular = 矩形
distribution-u-shaped = 反正弦
decision-heading = 数值与允差 ± U 的比较（ISO 14253-1 判定区）

## Axis report: test-plan findings
findings-heading = 检验规程检查
findings-none = 检验符合标准的检验规程：未违反任何规则。
col-severity = 严重程度
col-rule = 规则
col-clause = 条款
col-finding = 发现
severity-error = 错误
severity-warning = 警告

## Axis report: model check and diagnosis
diagnosis-heading = 模型检查和诊断
diagnosis-intro = 标准的参数基于一个未明示的模型：每个目标位置和方向上的系统偏差、一个反向差值，以及与时间无关、σ 单一的白噪声分散。axcheck 拟合该模型，按本检验自身的规程由其模拟检验，并指出测量中超出该模型的部分。
diagnosis-verdict = 模型检查结论：
col-effect = 效应
col-finding-evidence = 发现、估计值和证据
evidence = 证据：{ $evidence }
what-to-do = 处理建议：
detectable-heading = 本规程能确认的
detectable-note = （本规程 80 % 的检验能发现的大小）：
unconfirmed-heading = 检验中可见，但未被预测确认：
unconfirmed-note = 其项在留出数据上的增益不大于同样大小的无关项，故不作为发现，扩展模型不含此项。
held-out = 留出误差（{ $validation }）：基本模型 { $base } { $unit } RMS，扩展模型 { $extended } { $unit } RMS，增益 { $gain } %。
term-gains = 各项在能显示它的留出方案下：{ $list }。
model-terms = 基本项：{ $base }。扩展项：{ $extended }。
out-of-test = 检验之外：由本轴线的 { $from } 预测（其行程内 { $readings } 个读数，基准偏移 { $offset } { $unit } 之后）：基本模型（平滑系统偏差）{ $base } { $unit } RMS，扩展模型（目标位置偏差及保留项）{ $extended } { $unit } RMS；{ $intest }。时间项不计入：每次检验重新开始。
col-parameter-unit = 参数（{ $unit }）
as-measured = 实测
without = 去除 { $what }
checks-heading = 模型检查：实测统计量与由基本模型模拟的检验对比
time-effect-heading = 随时间的效应与各次运行均值的对比，及去除后的残差
residuals-time-heading = 随时间的残差
residuals-position-heading = 沿轴线的残差
periodogram-heading = 沿轴线系统偏差的周期图（Lomb–Scargle）

## Axis report: compensation table
compensation-heading = 补偿表（控制器 { $controller }）
compensation-refused = 未写出补偿表：{ $reason }。
compensation-parameters-heading = 实测参数与启用补偿表后的预测参数
col-unit = 单位
col-measured = 实测
col-predicted = 预测
compensation-predicted-note = 预测：本检验的读数按控制器所存的补偿表（其值修约到控制器单位，{ $applied }）代替检验时启用的补偿，重新评定。
compensation-chart-heading = 实测及加补偿表后的平均位置偏差
compensation-warnings-heading = 不宜补偿的情况
verification-heading = 验证：本检验复测上次测量以来装入的补偿表
verification-error = 无法进行验证：{ $error }。
verification-verdict = 结论：{ $verdict }。
verification-note = 预测：上次测量以补偿表的修正代替当时启用的修正。结论将实现的 E（GB/T 17421.2 2.20）与预测的 E 及之前的 E 比较，各差值与两次测量的分散所允许的不确定度比较。{ $notes }

## Axis report: inspection history
history-heading = 检验历史（{ $count } 次检验，{ $first } 至 { $last }）
history-first = 这是本轴线在历史中的第一次检验：趋势需要两次或更多。
history-flagged = { $total } 个参数中 { $flagged } 个被标记
history-flagged-within = { $flagged }（{ $years } 年期限内）。
history-none-flagged = { $years } 年期限内无参数被标记。
closing-note = 由 { $generator } 根据检验数据生成；位置为实测位置；数值单位为 { $unit }

## Campaign summary (summary.typ)
summary-title = 汇总
summary-kind = 定位精度检验汇总
summary-site = 现场
summary-purpose = 检验目的
summary-date = 日期
summary-campaign-file = 检验文件
summary-tests = 检验
summary-trends-heading = 检验历史的趋势（{ $first } 至 { $last }）
summary-trends-none = 这些轴线的 { $series } 个序列在 { $years } 年期限内均未被标记。
summary-trends-flagged = 这些轴线的 { $series } 个序列中有 { $flagged } 个在 { $years } 年期限内被标记（各轴线报告的“检验历史”一节列出）：
summary-machine-axis = 机床，轴线
summary-why = 原因
summary-axes-heading = 轴线（数值为轴线的单位；需关注者在前）
summary-travel = 行程
summary-worst = 最大占比 / 允差
summary-diagnosis = 诊断
summary-verdict = 判定
summary-no-tolerance = 无允差
summary-axes-note = A、E、R、B 按 GB/T 17421.2（GOST 27843 轴线的 R 和 B 为 R_max 和 B_max）；“–”：不适用（n = 1，第 5.2 条）或未评定。“最大占比 / 允差”：占其允差比例最大的参数。“诊断”：模型检查指出的超出标准模型的效应（无：模型能解释数据）。
chart-usage-axis = 最大占比参数 / 允差
chart-usage-empty = 没有可汇总的轴线。
chart-usage-within = 允差之内
chart-usage-over = 超出允差
chart-usage-limit = 允差
chart-usage-clipped = ▶ 比值大于 { $ratio }，条形已截断
summary-usage-heading = 允差占用比例（各轴线最大者）
summary-noncompliant-heading = 不符合规程的检验
summary-errors-heading = 错误
summary-inputs-heading = 输入
summary-inputs-intro = 由 axcheck { $version } 根据下列 { $total } 个文件用命令 { $command }（及输出文件夹）生成；在该文件夹上运行 { $reproduce } 将核对每个文件的 SHA-256，重新运行并逐字节比较输出。
summary-file = 文件
summary-sha = SHA-256（前 16 位）
summary-more-files = … 另有 { $more } 个文件。
summary-paths-note = 路径相对于检验文件所在的文件夹（模板和历史相对于所给的文件夹）；results.json 列出每个输入及其完整的 SHA-256。
summary-closing-note = 由 { $generator } 生成。各轴线报告：reports/MACHINE/AXIS.pdf。

## summary.html (page.js)
html-title = { $name } — axcheck 汇总
html-search = 搜索
html-search-placeholder = 机床、轴线、判定、规则、效应 …
html-keys = ↑ ↓ 移动，Enter 打开，Esc 关闭
html-counts-label = 显示某一判定的检验
html-headline-title = { $symbol } 及其扩展不确定度 U（k = 2），单位为该行的单位
html-worst-title = 占其允差比例最大的参数：|数值| / 允差
html-decision-rule = 判定规则
html-plan-rules = 规程规则
html-plan-rules-title = 违反的检验规程规则（不符合）；警告见详情
html-none = 无
html-compensation-e = 补偿 E
html-compensation-e-title = 实测 E → 用新补偿表预测的 E
html-trend = 趋势
html-trend-title = 在检验历史中趋势被标记的参数
html-flagged = 已标记：{ $list }
verdict-error-word = 错误
html-footer = { $generator }。数值单位为 µm（直线轴线）或角秒（回转轴线），2 位小数；U 为扩展不确定度（k = 2）。
html-inputs = 输入：{ $total } 个文件，由 axcheck { $version } 用 { $command } 生成
html-more-inputs = … 另有 { $more } 个（results.json 列出全部）
html-close = 关闭
html-limits = 允差
html-axis-report = 轴线报告（PDF）
html-compensation-table = 补偿表
html-value-unit = 数值 / { $unit }
html-u-unit = U（k = 2）/ { $unit }
html-limit-unit = 允差 / { $unit }
html-check = 检查
html-outcome-pass = 合格
html-outcome-fail = 不合格
html-outcome-inconclusive = 不确定
html-parameters = 参数
html-not-applicable = 此处不适用：{ $list }
html-rules = 检验规程规则
html-advice = 建议：{ $advice }
html-no-effect = 未发现超出误差模型的效应。
html-controller = 控制器 { $controller }，{ $mode } 补偿表
html-built-on = ，基于 { $file }
html-compensation-line = E { $text } { $unit }（实测 → 预测）
html-not-written = 未写出：{ $reason }
html-warning = 警告：{ $warning }
html-compensation = 补偿
html-verification = 验证
html-history = 历史
html-detail-unreadable = 此浏览器无法读取详情：{ $error }
html-chart-bidirectional = 双向位置偏差（GB/T 17421.2 图 2a）
html-chart-unidirectional = 单向位置偏差（GB/T 17421.2 图 2b）
html-chart-history = 历史：{ $label }

## Other laser tests (other-report.typ)
other-kind-straightness = 直线度检验报告（ISO 230-1）
other-kind-angular = 角度偏差检验报告（ISO 230-1）
other-kind-squareness = 垂直度检验报告（ISO 230-1）
other-from-to = { $from } 至 { $to }
other-from-straightness = 取自直线度检验
other-runs = 每个方向的测量次数
other-targets = 目标位置数
other-tolerance = 允差
other-none-stated = 未说明
other-chart-position = 目标位置 / { $unit }
other-chart-deviation = 相对 { $line } 直线的偏差 / { $unit }
other-chart-angular = 平均角度偏差 / { $unit }
other-outcome = 结果
other-cross-heading = 轴间补偿
other-uncertainty-heading = 测量不确定度（GUM）

## Inspection trends (trends.typ)
trends-kind = 检验趋势
trends-dates = { $count } 个日期，{ $first } 至 { $last }
trends-series = 序列
trends-series-value = { $count }（机床、轴线、参数）
trends-flagged = 已标记
trends-flagged-value = { $axes } 条轴线上的 { $series } 个序列
trends-horizon = 期限
trends-horizon-value = 最近一次检验后 { $years } 年
trends-charts-note = 图中：各次检验（点），通过它们的直线（实线）及延伸至期限（虚线），其带，允差（红色），最近一次检验（灰色虚线），以及期限内直线达到允差之处（红色菱形）。
trends-further-axes = 另有 { $count } 条轴线
trends-omitted = { $axes }（{ $flagged }）未在此作图：全部序列见 { $table }。
trends-omitted-flagged = 其中 { $count } 条被标记
trends-omitted-none = 均未被标记
trends-serial = （出厂编号 { $serial }）
trends-axis = 轴线 { $axis }
trends-closing-note = 由 axcheck 根据历史 { $history } 生成。全部序列及其数值：{ $table }。

## 参数名称：GB/T 17421.2-2000 第 2 章（2.13、2.14、2.18~2.23）
param-iso-A = 轴线双向定位精度
param-iso-A_up = 轴线单向定位精度 ↑
param-iso-A_down = 轴线单向定位精度 ↓
param-iso-E = 轴线双向定位系统偏差
param-iso-E_up = 轴线单向定位系统偏差 ↑
param-iso-E_down = 轴线单向定位系统偏差 ↓
param-iso-M = 轴线双向平均位置偏差
param-iso-R = 轴线双向重复定位精度
param-iso-R_up = 轴线单向重复定位精度 ↑
param-iso-R_down = 轴线单向重复定位精度 ↓
param-iso-B = 轴线反向差值
param-iso-B_mean = 轴线平均反向差值
# GOST 27843 的参数：按其定义译出，用 GB/T 17421.2 的对应术语。
param-gost-A = 双向定位精度
param-gost-A_up = 单向定位精度 ↑
param-gost-A_down = 单向定位精度 ↓
param-gost-R_max = 双向重复定位精度
param-gost-R_up = 单向重复定位精度 ↑
param-gost-R_down = 单向重复定位精度 ↓
param-gost-R_mean = 平均双向重复定位精度
param-gost-B_max = 最大反向差值
param-gost-B_mean = 平均反向差值

## Certificate of a calibration laboratory (certificate.typ; ISO/IEC 17025:2017 7.8)
cert-title = 校准证书
cert-number = 编号 { $number }
cert-customer = 委托方
cert-laboratory = 实验室
cert-date-measured = 测量日期
cert-date-issued = 签发日期
cert-place = 地点
cert-method = 方法
cert-deviations = 偏离方法之处
cert-deviations-none = 无
cert-traceability-heading = 测量仪器的溯源性
cert-col-instrument = 仪器
cert-col-serial = 出厂编号
cert-col-certificate = 校准证书
cert-col-calibrated = 校准日期
cert-col-due = 有效期至
cert-col-body = 校准机构
cert-not-stated = 未说明
cert-statement = 本证书的结果经上述仪器的校准溯源至国际单位制（SI）的长度单位米，各仪器在测量日期均在校准有效期内。结果仅对被校准的对象有效。未经实验室书面批准，不得部分复制本证书。
cert-authorised-by = 批准人
cert-signature = 签字，签发日期 { $date }
method-straightness = ISO 230-1:2012（直线度）
method-angular = ISO 230-1:2012（角度偏差）
method-squareness = ISO 230-1:2012（垂直度）
as-found-heading = 调整前与调整后（单位：{ $unit }）
as-found-intro = 两次测量之间对轴线作了调整：调整前（{ $found }），判定 { $found_verdict }；调整后（{ $left }），判定 { $left_verdict }。两者按相同的允差和相同的判定规则判定。
col-as-found = 调整前
col-as-left = 调整后

## Conditions' values (conditions.rs)
unit-mm-per-min = mm/min
unit-deg-per-min = °/min
unit-kpa = kPa
unit-rh = 相对湿度 { $value } %
nde-alpha = ；α = { $alpha } µm/(m·°C)
nde-applied = 由 axcheck 修正到 20 °C：α = { $alpha } µm/(m·°C)，平均温度 { $mean } °C（{ $source }）；最大修正量 { $max } µm
nde-in-data = 已修正，数据中由测量仪器修正{ $alpha }
nde-not-applied = 未修正（未给出温度）{ $alpha }
sensor-kind-material = 材料
sensor-kind-air = 空气

## What a test was judged by (axis.rs spec_words)
spec-no-tolerance = 未采用允差
spec-plus-axis = { $spec } + 轴线允差
spec-axis-tolerances = 轴线允差
spec-example = { $spec } — 示例允差，非出自标准

## A verdict's uncertainty, large (axis.rs large_uncertainty)
large-u = { $symbol } = { $value } ± { $u } { $unit }，允差 { $limit } { $unit }：{ $why }
large-u-why-both = U 超过允差的一半且超过测得值
large-u-why-half = U 超过允差的一半
large-u-why-value = U 超过测得值

## An instrument with its serial number; the purposes of a test (ISO 230-2 clause 1)
instrument-serial = { $name }，编号 { $serial }
purpose-periodic = 定期
purpose-acceptance = 验收
purpose-comparison = 比对
purpose-type = 型式
purpose-compensation = 补偿

## Standards' titles in this language (Words::standard; the others as axcheck writes them)
standard-gost27843 = GOST 27843-88
standard-gbt17421-2 = GB/T 17421.2-2000（等效采用 ISO 230-2:1997，含第 1 号修改单）

## summary.html's count of the rows shown (page.js)
html-shown-count = 显示 { $shown } / { $total } 项检验

## The diagnosis's residual charts and periodogram (data/diagnosis.rs, charts/diagnosis)
diag-x-time = 自检验开始的时间 / min
diag-x-order = 按检验循环顺序的读数
diag-y-residual = 残差 / { $unit }
diag-period = 周期 / { $unit }
diag-residual-up = 残差 ↑
diag-residual-down = 残差 ↓
diag-band = 基本模型 ±2σ（±{ $value }）

## The model check's statistics (data/diagnosis.rs; diagnose::checks names them)
check-run-mean-spread = 各次运行平均值的离散
check-lag1-autocorrelation = 滞后 1 自相关
check-max-studentized-residual = 最大学生化残差
check-reversal-range = 反向差值极差
check-scatter-ratio-end-to-start = 终端与始端散布之比
check-periodogram-max-f = 周期图最大 F 值
check-trend-lack-of-fit-rms = 趋势失拟均方根
