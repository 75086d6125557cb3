# axcheck's report words in English. The same keys in zh.ftl and ru.ftl (a test compares
# the key sets and the arguments each message uses). Arguments are `{ $name }`; the
# templates replace `{name}` in the strings of `t` (data.json).

## Page and shared tables (style.typ)
page-of = Page { $page } of { $total }
col-parameter = Parameter
col-value = Value
col-u = U (k = 2)
col-limit = Limit
col-margin = Margin
col-status = Status
status-pass = pass
status-fail = FAIL
status-na = n/a
status-inconclusive = inconclusive
col-inspections = Inspections
col-latest = Latest
col-slope = Slope
col-reaches-limit = Reaches the limit
trend-flagged = flagged
trend-method = Slope: the Theil–Sen median of the pairwise slopes per year (robust to one odd inspection), ± its standard error from Sen’s 95 % interval; the band on the charts is that interval’s two slopes through the line’s middle. “Reaches the limit”: where the line meets the latest limit (|B̄| for B̄). A series is flagged when the line reaches its limit within the horizon, is over it, or worsens significantly (95 %) by at least a tenth of its limit within the horizon.

## Units
unit-um = µm
unit-mm = mm
unit-arcsec = arcsec
unit-s = s

## Verdicts
verdict-pass = PASS
verdict-fail = FAIL
verdict-noncompliant = NONCOMPLIANT
verdict-error = ERROR
verdict-inconclusive = INCONCLUSIVE
verdict-not-judged = NOT JUDGED
verdict-detail-not-judged = Not judged: no tolerance applied, so nothing was compared with a limit; evaluated and checked against the test-plan rules only.
verdict-detail-pass-one = The limited value is within tolerance.
verdict-detail-pass-all = All { $count } limited parameters are within tolerance.
verdict-detail-fail = Over the limit: { $symbols }.
verdict-detail-noncompliant = The test does not follow the standard's plan ({ $rules }): its results cannot be used for acceptance.
verdict-detail-inconclusive = Within the uncertainty of the measurement at the limit (ISO 14253-1: limit ± U): { $zone }. Neither conformance nor nonconformance is proven.
verdict-zone = { $symbol } = { $value } ± { $u } { $unit } against { $limit } { $unit }
verdict-large-uncertainty = { $detail } The uncertainty is large for this verdict: { $list }.

## Axis report: header
axis-report-kind = Positioning accuracy and repeatability test report
axis-title = { $machine } — axis { $axis }
purpose-inspection = { $purpose } inspection
in-full-below = { $name } (in full below)
fact-machine-in-full = Machine, in full
fact-axis-in-full = Axis, in full
fact-machine = Machine
fact-machine-in-file = Machine in the file
fact-model = Model
fact-serial = Serial number
fact-type = Type
fact-location = Location
fact-axis = Axis
fact-axis-in-file = Axis in the file
fact-axis-travel = Axis travel
fact-measurement-travel = Measurement travel
fact-measurement-file = Measurement file
fact-file-sha = File SHA-256
fact-test = Test
fact-test-of = { $test } of { $tests } tests of this axis
fact-standard = Standard
fact-spec = Acceptance spec
fact-date = Test date
fact-inspector = Inspector
from-measurement-file = { $value } (measurement file)
axis-kind-linear = linear
axis-kind-rotary = rotary

## Axis report: test conditions
conditions-heading = Test conditions (ISO 230-2 7.1)
cond-instrument = Measuring instrument
cond-instrument-position = Position of the instrument
cond-equipment = Test equipment
cond-positioning-element = Positioning element
cond-nde = NDE correction (3.1)
cond-feed = Feed rate
cond-dwell = Dwell at each target
cond-compensation = Compensation active (3.2)
cond-other-axes = Positions of the other axes (3.2)
cond-tool-offset = Tool offset
cond-workpiece-offset = Workpiece offset
cond-warm-up = Warm-up (3.3)
cond-cycle = Test cycle
cond-air = Air (start → end)
cond-pressure = Pressure of air or oil
cond-approaches = Approaches per direction
cond-approaches-value = n = { $n } at each of { $targets } targets
cond-read-as = Measurement file read as
cond-from-file = Taken from the measurement file
cond-notes = Notes
cond-not-stated = not stated
cycle-standard = standard test cycle (ISO 230-2 Fig. 1)
cycle-step = step cycle (ISO 230-2 Annex A)
cycle-pilgrim = pilgrim-step cycle (GOST 27843 Черт. 2)
unstated-instrument-position = Position of the measuring instrument
unstated-sensor-positions = Positions of the temperature sensors
unstated-model = Machine model
unstated-type = Machine type
unstated-equipment = Test equipment (maker, type, serial numbers)
unstated-expansion = Expansion coefficient of the positioning element
unstated-offsets = Tool and workpiece offsets
unstated-material = Material temperatures at start and end
unstated-air = Air temperature at start and end
unstated-pressure = Air pressure and humidity at start and end
unstated-compensation = Compensation active during the test (3.2)
sensor-heading = Temperature sensor
sensor-kind = Kind
sensor-position = Position
sensor-start = Start
sensor-end = End

## Axis report: results
results-heading = Results (values in { $unit })
note = Note: { $note }
at-target = at i = { $i } ({ $position })
not-applicable = not applicable
fig-bidirectional = Bidirectional accuracy and repeatability (like ISO 230-2 Fig. 2a)
fig-unidirectional = Unidirectional accuracy and repeatability (like ISO 230-2 Fig. 2b)
chart-approach = Approach { $arrow }
chart-mean = mean X̄i{ $arrow }
chart-readings = readings { $arrow }
chart-mean-bidirectional = mean X̄i (bidirectional)
chart-target-position = Target position Pi / { $unit }
target-position = Position Pi
chart-positional-deviation = Positional deviation / { $unit }
targets-heading = Per-target results ({ $unit }, layout of ISO 230-2 Table 2)
target-direction = Direction

## Axis report: the results of the tool that wrote the file
other-tool-heading = Results of the { $name } in the file, beside axcheck’s
other-tool-intro = The file carries the results its tool computed{ $state }. axcheck evaluates the same readings by ISO 230-2; the two agree when they differ by no more than the tool’s rounding and the readings’ rounding explain.
other-tool-state = { " " }(state: { $state })
other-tool-its-result = Its result
other-tool-as-printed = As printed
other-tool-theirs = Theirs ({ $unit })
other-tool-ours = axcheck ({ $unit })
other-tool-difference = Difference
other-tool-agree = agree
other-tool-differ = differ
other-tool-not-compared = Not ISO 230-2 parameters, not compared: { $list }.

## Axis report: at the tool point
tool-point-heading = At the tool point (Abbe)
tool-point-error = The test could not be carried to the tool point: { $error }
tool-point-intro = The laser measured this axis on its beam; the tool point lies at { $offsets } from the beam, across the axis. Each reading is carried there through the axis’s angular tests { $rotations }: the offset times the tangent of the angle at its target and direction (HP 5528A User’s Guide, Appendix B), then evaluated and judged as measured.
tool-point-verdicts = Verdict at the beam: { $beam }; at the tool point: { $tool }
tool-point-changes = the rotations change the verdict
tool-point-at-beam = At the beam ({ $unit })
tool-point-at-tool = At the tool point ({ $unit })
tool-point-outcome = At the tool point

## Axis report: uncertainty
uncertainty-heading = Measurement uncertainty (GUM, k = 2)
uncertainty-intro = Budget over the measurement travel ({ $length }): combined standard uncertainty u{ $c } = { $combined } { $unit }, expanded uncertainty U = 2u{ $c } = { $expanded } { $unit }. Each parameter’s U in the results table is the budget over the length it spans, with the statistics of its own estimates.
col-contributor = Contributor
col-distribution = Distribution
col-share = Share
check-model-empty = No model checks to show.
check-model-band-key = simulated 95 % band (base model)
check-model-band-head = simulated 95 % band
check-model-band-head-narrow = 95 % band
check-model-measured = measured
check-model-outside = measured, check outside
check-model-scale = each statistic on its own scale
check-decision-empty = No limited parameters to show.
check-decision-band-key = limit ± U: inconclusive zone (ISO 14253-1)
check-decision-band-head = limit − U … limit + U
check-decision-band-head-narrow = limit ± U
check-decision-value = value
check-decision-outside = value, nonconformance proven
check-decision-scale = each parameter on its own scale
check-beyond = beyond the scale
contributor-air-humidity = air humidity
contributor-air-pressure = air pressure
contributor-air-temperature = air temperature
contributor-calibration = calibration
contributor-dead-path = dead path
contributor-expansion-coefficient = expansion coefficient
contributor-instrument-repeatability = instrument repeatability
contributor-material-temperature = material temperature
contributor-mean-of-n = mean of n
contributor-misalignment = misalignment
contributor-resolution = resolution
contributor-s-of-n = s of n
contributor-temperature-change = temperature change
contributor-uncorrected-expansion = uncorrected expansion
contributor-repeatability = repeatability
contributor-optics = optics
distribution-normal = normal
distribution-rectangular = rectangular
distribution-u-shaped = u-shaped
decision-heading = Value against the limit ± U (ISO 14253-1 decision zones)

## Axis report: test-plan findings
findings-heading = Test-plan findings
findings-none = The test follows the standard’s plan: no rule is broken.
col-severity = Severity
col-rule = Rule
col-clause = Clause
col-finding = Finding
severity-error = error
severity-warning = warning

## Axis report: model check and diagnosis
diagnosis-heading = Model check and diagnosis
diagnosis-intro = The standard’s parameters assume a model it never states: a systematic deviation at each target and direction, one reversal value, and white scatter with one σ that does not depend on time. axcheck fits that model, simulates tests from it with this test’s own plan, and names what the measurement shows beyond it.
diagnosis-verdict = Verdict of the model check:
col-effect = Effect
col-finding-evidence = Finding, estimate and evidence
evidence = Evidence: { $evidence }
what-to-do = What to do:
detectable-heading = What this plan can confirm
detectable-note = (the size found in 80 % of tests with this plan):
unconfirmed-heading = Seen by its test, not confirmed by prediction:
unconfirmed-note = its term gains no more held out than unrelated terms of the same size, so it is no finding and the extended model leaves it out.
held-out = Held-out error ({ $validation }): base model { $base } { $unit } RMS, extended model { $extended } { $unit } RMS, gain { $gain } %.
term-gains = Per term, under the held-out scheme that can show it: { $list }.
model-terms = Base terms: { $base }. Extended terms: { $extended }.
out-of-test = Out of test: predicted from { $from } of this axis ({ $readings } readings inside its travel, after a datum offset of { $offset } { $unit }): base model (smooth systematic deviation) { $base } { $unit } RMS, extended model (deviation at its targets and its kept terms) { $extended } { $unit } RMS; { $intest }. Time terms are left out: they restart with each test.
col-parameter-unit = Parameter ({ $unit })
as-measured = as measured
without = without { $what }
checks-heading = Model check: measured statistics against tests simulated from the base model
time-effect-heading = The effect in time against the run means, and the residuals after it
residuals-time-heading = Residuals in time
residuals-position-heading = Residuals along the axis
periodogram-heading = Periodogram of the systematic deviation along the axis (Lomb–Scargle)

## Axis report: compensation table
compensation-heading = Compensation table (controller { $controller })
compensation-refused = No table is written: { $reason }.
compensation-parameters-heading = Parameters measured and predicted with the table active
col-unit = Unit
col-measured = Measured
col-predicted = Predicted
compensation-predicted-note = Predicted: this test’s readings with the table applied as the controller holds it (its values rounded to the controller’s unit, { $applied }), in place of the compensation active during the test, evaluated again.
compensation-chart-heading = Mean positional deviations as measured and with the table
compensation-warnings-heading = When not to compensate
verification-heading = Verification: this test re-measures the table loaded since the measurement before
verification-error = The verification could not be made: { $error }.
verification-verdict = Verdict: { $verdict }.
verification-note = Predicted: the measurement before with the table’s correction in place of the one active then. The verdict compares E (ISO 230-2 2.20) achieved with E predicted and with E before, each difference against the uncertainty the two measurements’ scatter allows. { $notes }

## Axis report: inspection history
history-heading = Inspection history ({ $count } inspections, { $first } to { $last })
history-first = This is the axis’s first inspection in the history: a trend needs two or more.
history-flagged = { $flagged } of { $total } parameters flagged
history-flagged-within = { $flagged } within the { $years }-year horizon.
history-none-flagged = No parameter is flagged within the { $years }-year horizon.
closing-note = Produced by { $generator } from the campaign data; values in { $unit }, positions as measured.

## Campaign summary (summary.typ)
summary-title = summary
summary-kind = Positioning accuracy campaign summary
summary-site = Site
summary-purpose = Purpose
summary-date = Date
summary-campaign-file = Campaign file
summary-tests = tests
summary-trends-heading = Trends over the inspection history ({ $first } to { $last })
summary-trends-none = None of the { $series } series of these axes is flagged within the { $years }-year horizon.
summary-trends-flagged = { $flagged } of the { $series } series of these axes are flagged within the { $years }-year horizon (each axis report’s section “Inspection history” shows them):
summary-machine-axis = Machine, axis
summary-why = Why
summary-axes-heading = Axes (values in the axis’s unit; needing attention first)
summary-travel = Travel
summary-worst = Worst / limit
summary-diagnosis = Diagnosis
summary-verdict = Verdict
summary-no-tolerance = no tolerance
summary-axes-note = A, E, R, B per ISO 230-2 (R and B are R_max and B_max for GOST 27843 axes); “–”: not applicable (n = 1, clause 5.2) or not evaluated. “Worst / limit”: the parameter using the largest share of its tolerance. “Diagnosis”: the effects the model check names beyond the standard’s model (none: the model explains the data).
chart-usage-axis = Worst parameter / tolerance
chart-usage-empty = No axes to summarise.
chart-usage-within = within tolerance
chart-usage-over = over tolerance
chart-usage-limit = limit
chart-usage-clipped = ▶ ratio above { $ratio }, bar clipped
summary-usage-heading = Share of tolerance used (worst parameter of each axis)
summary-noncompliant-heading = Noncompliant test plans
summary-errors-heading = Errors
summary-inputs-heading = Inputs
summary-inputs-intro = Made by axcheck { $version } from the { $total } files below with the command { $command } (and the output folder); { $reproduce } on that folder checks each file’s SHA-256, runs the campaign again and compares the outputs byte for byte.
summary-file = File
summary-sha = SHA-256 (first 16 digits)
summary-more-files = … and { $more } more files.
summary-paths-note = Paths relative to the campaign’s folder (templates and history after their folder as given); results.json lists every input with its whole SHA-256.
summary-closing-note = Produced by { $generator }. Per-axis reports: reports/MACHINE/AXIS.pdf.

## summary.html (page.js)
html-title = { $name } — axcheck summary
html-search = Search
html-search-placeholder = machine, axis, verdict, rule, effect …
html-keys = ↑ ↓ move, Enter opens, Esc closes
html-counts-label = Show the tests of one verdict
html-headline-title = { $symbol } with its expanded uncertainty U (k = 2), in the row’s unit
html-worst-title = The parameter using the largest share of its tolerance: |value| / limit
html-decision-rule = Decision rule
html-plan-rules = Plan rules
html-plan-rules-title = Test-plan rules broken (noncompliant); warnings in the detail
html-none = none
html-compensation-e = Compensation E
html-compensation-e-title = E as measured → as predicted with the new table
html-trend = Trend
html-trend-title = Parameters whose trend over the inspection history is flagged
html-flagged = flagged: { $list }
verdict-error-word = Error
html-footer = { $generator }. Values in µm (linear axes) or arcsec (rotary axes), 2 decimals; U is the expanded uncertainty (k = 2).
html-inputs = Inputs: { $total } files, made by axcheck { $version } with { $command }
html-more-inputs = … and { $more } more (results.json lists them all)
html-close = Close
html-limits = Limits
html-axis-report = Axis report (PDF)
html-compensation-table = Compensation table
html-value-unit = Value / { $unit }
html-u-unit = U (k = 2) / { $unit }
html-limit-unit = Limit / { $unit }
html-check = Check
html-outcome-pass = pass
html-outcome-fail = fail
html-outcome-inconclusive = inconclusive
html-parameters = Parameters
html-not-applicable = Not applicable here: { $list }
html-rules = Test-plan rules
html-advice = Advice: { $advice }
html-no-effect = No effect found beyond the error model.
html-controller = Controller { $controller }, { $mode } table
html-built-on = , built on { $file }
html-compensation-line = E { $text } { $unit } (measured → predicted)
html-not-written = Not written: { $reason }
html-warning = Warning: { $warning }
html-compensation = Compensation
html-verification = Verification
html-history = History
html-detail-unreadable = The detail could not be read in this browser: { $error }
html-chart-bidirectional = Bidirectional positional deviations (ISO 230-2 Fig. 2a)
html-chart-unidirectional = Unidirectional positional deviations (ISO 230-2 Fig. 2b)
html-chart-history = History: { $label }

## Other laser tests (other-report.typ)
other-kind-straightness = Straightness test report (ISO 230-1)
other-kind-angular = Angular deviation test report (ISO 230-1)
other-kind-squareness = Squareness test report (ISO 230-1)
other-from-to = { $from } to { $to }
other-from-straightness = From the straightness tests
other-runs = Runs per direction
other-targets = Targets
other-tolerance = Tolerance
other-none-stated = none stated
other-chart-position = Target position / { $unit }
other-chart-deviation = Deviation about the { $line } line / { $unit }
other-chart-angular = Mean angular deviation / { $unit }
other-outcome = Outcome
other-cross-heading = Cross-axis compensation
other-uncertainty-heading = Measurement uncertainty (GUM)

## Inspection trends (trends.typ)
trends-kind = Inspection trends
trends-dates = { $count } dates, { $first } to { $last }
trends-series = Series
trends-series-value = { $count } (machine, axis, parameter)
trends-flagged = Flagged
trends-flagged-value = { $series } series on { $axes } axes
trends-horizon = Horizon
trends-horizon-value = { $years } years after the latest inspection
trends-charts-note = On the charts: the inspections (dots), the line through them (solid) and ahead to the horizon (dashed), its band, the limit (red), the latest inspection (grey dashed) and, within the horizon, where the line reaches the limit (red diamond).
trends-further-axes = { $count } further axes
trends-omitted = { $axes } ({ $flagged }) are not charted here: every series is in { $table }.
trends-omitted-flagged = { $count } of them flagged
trends-omitted-none = none of them flagged
trends-serial = (serial { $serial })
trends-axis = axis { $axis }
trends-closing-note = Produced by axcheck from the history { $history }. Every series with its numbers: { $table }.

## Parameter names as each standard words them (ISO 230-2; GOST 27843-88; VDI 3441 and
## NMTBA as described by Hemingray, Cowley and Burdekin)
param-iso-A = bidirectional accuracy of positioning
param-iso-A_up = unidirectional accuracy of positioning ↑
param-iso-A_down = unidirectional accuracy of positioning ↓
param-iso-E = bidirectional systematic positional deviation
param-iso-E_up = unidirectional systematic positional deviation ↑
param-iso-E_down = unidirectional systematic positional deviation ↓
param-iso-M = range of the mean bidirectional positional deviation
param-iso-R = bidirectional repeatability of positioning
param-iso-R_up = unidirectional repeatability of positioning ↑
param-iso-R_down = unidirectional repeatability of positioning ↓
param-iso-B = reversal value of the axis
param-iso-B_mean = mean reversal value of the axis
param-gost-A = bidirectional positioning accuracy
param-gost-A_up = unidirectional positioning accuracy ↑
param-gost-A_down = unidirectional positioning accuracy ↓
param-gost-R_max = bidirectional positioning repeatability
param-gost-R_up = unidirectional positioning repeatability ↑
param-gost-R_down = unidirectional positioning repeatability ↓
param-gost-R_mean = mean bidirectional positioning repeatability
param-gost-B_max = maximum dead band (reversal)
param-gost-B_mean = mean dead band (reversal)

## Certificate of a calibration laboratory (certificate.typ; ISO/IEC 17025:2017 7.8)
cert-title = Calibration certificate
cert-number = No. { $number }
cert-customer = Customer
cert-laboratory = Laboratory
cert-date-measured = Date of measurement
cert-date-issued = Date of issue
cert-place = Place
cert-method = Method
cert-deviations = Deviations from the method
cert-deviations-none = none
cert-traceability-heading = Traceability of the instruments
cert-col-instrument = Instrument
cert-col-serial = Serial number
cert-col-certificate = Certificate
cert-col-calibrated = Calibrated on
cert-col-due = Due
cert-col-body = Calibrated by
cert-not-stated = not stated
cert-statement = The results are traceable to the SI unit of length, the metre, through the calibrations of the instruments above, each valid on the date of measurement. They relate only to the item calibrated. This report shall not be reproduced except in full without the written approval of the laboratory.
cert-authorised-by = Authorised by
cert-signature = Signature, date of issue { $date }
method-straightness = ISO 230-1:2012 (straightness)
method-angular = ISO 230-1:2012 (angular deviation)
method-squareness = ISO 230-1:2012 (squareness)
as-found-heading = As found and as left (values in { $unit })
as-found-intro = The axis was adjusted between two measurements: as found ({ $found }), verdict { $found_verdict }; as left ({ $left }), verdict { $left_verdict }. Both are judged against the same limits with the same decision rule.
col-as-found = As found
col-as-left = As left

## Conditions' values (conditions.rs)
unit-mm-per-min = mm/min
unit-deg-per-min = °/min
unit-kpa = kPa
unit-rh = { $value } % RH
nde-alpha = ; α = { $alpha } µm/(m·°C)
nde-applied = applied by axcheck to 20 °C: α = { $alpha } µm/(m·°C), mean temperature { $mean } °C from { $source }; largest correction { $max } µm
nde-in-data = yes, in the data (by the instrument){ $alpha }
nde-not-applied = not applied (no temperature given){ $alpha }
sensor-kind-material = material
sensor-kind-air = air

## What a test was judged by (axis.rs spec_words)
spec-no-tolerance = no tolerance applied
spec-plus-axis = { $spec } + axis tolerances
spec-axis-tolerances = axis tolerances
spec-example = { $spec } — example limits, not from a standard

## A verdict's uncertainty, large (axis.rs large_uncertainty)
large-u = { $symbol } = { $value } ± { $u } { $unit } against its limit { $limit } { $unit }: { $why }
large-u-why-both = U over half its limit and over the value
large-u-why-half = U over half its limit
large-u-why-value = U over the value

## An instrument with its serial number; the purposes of a test (ISO 230-2 clause 1)
instrument-serial = { $name }, s/n { $serial }
purpose-periodic = periodic
purpose-acceptance = acceptance
purpose-comparison = comparison
purpose-type = type
purpose-compensation = compensation

## Standards' titles in this language (Words::standard; the others as axcheck writes them)
standard-gost27843 = GOST 27843-88
standard-gbt17421-2 = GB/T 17421.2-2000 (eqv ISO 230-2:1997, amendment No. 1)

## summary.html's count of the rows shown (page.js)
html-shown-count = { $shown } of { $total } tests

## The diagnosis's residual charts and periodogram (data/diagnosis.rs, charts/diagnosis)
diag-x-time = Time since the start of the test / min
diag-x-order = Reading in the order of the test cycle
diag-y-residual = Residual of the base model / { $unit }
diag-period = Period / { $unit }
diag-residual-up = residual ↑
diag-residual-down = residual ↓
diag-band = base model ±2σ (±{ $value })

## The model check's statistics (data/diagnosis.rs; diagnose::checks names them)
check-run-mean-spread = run mean spread
check-lag1-autocorrelation = lag1 autocorrelation
check-max-studentized-residual = max studentized residual
check-reversal-range = reversal range
check-scatter-ratio-end-to-start = scatter ratio end to start
check-periodogram-max-f = periodogram max F
check-trend-lack-of-fit-rms = trend lack of fit rms
