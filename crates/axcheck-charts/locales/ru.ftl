# Слова отчётов axcheck на русском языке. Ключи те же, что в en.ftl и zh.ftl (тест сравнивает
# наборы ключей и аргументы каждого сообщения). Десятичная запятая (7,27), даты ДД.ММ.ГГГГ.
#
# Термины: для испытаний по ГОСТ 27843-88 — термины его раздела 1 (1.10–1.16) дословно. Для
# ISO 230-2 русская версия — ГОСТ ISO 230-2-2016; его полный текст недоступен (найден лишь
# фрагмент раздела 6.2 с «однонаправленной повторяемостью» и «погрешностями
# позиционирования»), поэтому параметры ISO 230-2 названы терминами ГОСТ 27843-88
# (точность позиционирования, повторяемость, зона нечувствительности), а E и M — по смыслу
# определений ISO 230-2 (2.19–2.21).

## Page and shared tables (style.typ)
page-of = Страница { $page } из { $total }
col-parameter = Параметр
col-value = Значение
col-u = U (k = 2)
col-limit = Допуск
col-margin = Запас
col-status = Статус
status-pass = годен
status-fail = НЕ ГОДЕН
status-na = н/п
status-inconclusive = не определён
col-inspections = Проверок
col-latest = Последнее
col-slope = Наклон
col-reaches-limit = Достигнет допуска
trend-flagged = отмечен
trend-method = Наклон: медиана Тейла–Сена попарных наклонов за год (устойчива к одной выпадающей проверке), ± её стандартная погрешность по 95 % интервалу Сена; полоса на графиках — два наклона этого интервала через середину прямой. «Достигнет допуска»: где прямая пересекает последний допуск (|B̄| для B̄). Ряд отмечается, если прямая достигает допуска в пределах горизонта, уже выше него или значимо (95 %) ухудшается в пределах горизонта не менее чем на десятую часть допуска.

## Units
unit-um = мкм
unit-mm = мм
unit-arcsec = угл. с
unit-s = с

## Verdicts
verdict-pass = ГОДЕН
verdict-fail = НЕ ГОДЕН
verdict-noncompliant = НЕ ПО ПРОГРАММЕ
verdict-error = ОШИБКА
verdict-inconclusive = НЕ ОПРЕДЕЛЁН
verdict-not-judged = НЕ ОЦЕНЁН
verdict-detail-not-judged = Не оценён: допуски не заданы, ни одно значение не сравнивалось с допуском; выполнены только расчёт и проверка по правилам программы испытаний.
verdict-detail-pass-one = Нормируемое значение в пределах допуска.
verdict-detail-pass-all = Все нормируемые параметры ({ $count }) в пределах допуска.
verdict-detail-fail = Сверх допуска: { $symbols }.
verdict-detail-noncompliant = Испытание не следует программе стандарта ({ $rules }): его результаты нельзя использовать для приёмки.
verdict-detail-inconclusive = В пределах неопределённости измерения у допуска (ISO 14253-1: допуск ± U): { $zone }. Ни соответствие, ни несоответствие не доказано.
verdict-zone = { $symbol } = { $value } ± { $u } { $unit } при допуске { $limit } { $unit }
verdict-large-uncertainty = { $detail } Неопределённость велика для этого заключения: { $list }.

## Axis report: header
axis-report-kind = Протокол проверки точности и повторяемости позиционирования
axis-title = { $machine } — ось { $axis }
purpose-inspection = проверка: { $purpose }
in-full-below = { $name } (полностью ниже)
fact-machine-in-full = Станок, полностью
fact-axis-in-full = Ось, полностью
fact-machine = Станок
fact-machine-in-file = Станок в файле
fact-model = Модель
fact-serial = Заводской номер
fact-type = Тип
fact-location = Место
fact-axis = Ось
fact-axis-in-file = Ось в файле
fact-axis-travel = Ход по оси
fact-measurement-travel = Длина измерения
fact-measurement-file = Файл измерений
fact-file-sha = SHA-256 файла
fact-test = Испытание
fact-test-of = { $test }-е из { $tests } испытаний этой оси
fact-standard = Стандарт
fact-spec = Нормы приёмки
fact-date = Дата проверки
fact-inspector = Проверяющий
from-measurement-file = { $value } (файл измерений)
axis-kind-linear = линейная
axis-kind-rotary = поворотная

## Axis report: test conditions
conditions-heading = Условия проверки (ISO 230-2, 7.1)
cond-instrument = Средство измерения
cond-instrument-position = Положение средства измерения
cond-equipment = Испытательное оборудование
cond-positioning-element = Позиционируемый элемент
cond-nde = Поправка на температурное расширение (3.1)
cond-feed = Скорость подачи
cond-dwell = Выдержка в каждом положении
cond-compensation = Включённая коррекция (3.2)
cond-other-axes = Положения других осей (3.2)
cond-tool-offset = Коррекция инструмента
cond-workpiece-offset = Смещение заготовки
cond-warm-up = Прогрев (3.3)
cond-cycle = Цикл проверки
cond-air = Воздух (начало → конец)
cond-pressure = Давление воздуха или масла
cond-approaches = Подходов в каждом направлении
cond-approaches-value = n = { $n } в каждом из { $targets } заданных положений
cond-read-as = Файл измерений прочитан как
cond-from-file = Взято из файла измерений
cond-notes = Примечания
cond-not-stated = не указано
cycle-standard = стандартный цикл (ISO 230-2, рис. 1)
cycle-step = ступенчатый цикл (ISO 230-2, приложение A)
cycle-pilgrim = цикл «шаг пилигрима» (ГОСТ 27843, черт. 2)
unstated-instrument-position = Положение средства измерения
unstated-sensor-positions = Места датчиков температуры
unstated-model = Модель станка
unstated-type = Тип станка
unstated-equipment = Испытательное оборудование (изготовитель, тип, номера)
unstated-expansion = Коэффициент расширения позиционируемого элемента
unstated-offsets = Коррекции инструмента и заготовки
unstated-material = Температуры материала в начале и в конце
unstated-air = Температура воздуха в начале и в конце
unstated-pressure = Давление и влажность воздуха в начале и в конце
unstated-compensation = Коррекция, включённая при проверке (3.2)
sensor-heading = Датчик температуры
sensor-kind = Вид
sensor-position = Место
sensor-start = Начало
sensor-end = Конец

## Axis report: results
results-heading = Результаты (значения в { $unit })
note = Примечание: { $note }
at-target = в положении i = { $i } ({ $position })
not-applicable = не применяется
fig-bidirectional = Точность и повторяемость двустороннего позиционирования (как ISO 230-2, рис. 2a)
fig-unidirectional = Точность и повторяемость одностороннего позиционирования (как ISO 230-2, рис. 2b)
chart-approach = Подход { $arrow }
chart-mean = среднее X̄i{ $arrow }
chart-readings = отсчёты { $arrow }
chart-mean-bidirectional = среднее X̄i (двустороннее)
chart-target-position = Заданное положение Pi / { $unit }
target-position = Положение Pi
chart-positional-deviation = Отклонение от заданного положения / { $unit }
targets-heading = Результаты по заданным положениям ({ $unit }, в форме таблицы 2 ISO 230-2)
target-direction = Направление

## Axis report: the results of the tool that wrote the file
other-tool-heading = Результаты { $name } из файла рядом с результатами axcheck
other-tool-intro = Файл содержит результаты, рассчитанные его программой{ $state }. axcheck обрабатывает те же отсчёты по ISO 230-2; результаты совпадают, если различаются не более, чем объясняют округления программы и отсчётов.
other-tool-state = { " " }(состояние: { $state })
other-tool-its-result = Её результат
other-tool-as-printed = Как напечатано
other-tool-theirs = Её значение ({ $unit })
other-tool-ours = axcheck ({ $unit })
other-tool-difference = Разность
other-tool-agree = совпадает
other-tool-differ = различается
other-tool-not-compared = Не параметры ISO 230-2, не сравнивались: { $list }.

## Axis report: at the tool point
tool-point-heading = В точке инструмента (Аббе)
tool-point-error = Результаты нельзя перенести в точку инструмента: { $error }
tool-point-intro = Лазер измерял эту ось на своём луче; точка инструмента лежит на расстоянии { $offsets } от луча поперёк оси. Каждый отсчёт переносится туда по угловым проверкам оси { $rotations }: смещение, умноженное на тангенс угла в данном положении и направлении (HP 5528A User's Guide, приложение B), затем обрабатывается и оценивается как измеренный.
tool-point-verdicts = Заключение на луче: { $beam }; в точке инструмента: { $tool }
tool-point-changes = повороты меняют заключение
tool-point-at-beam = На луче ({ $unit })
tool-point-at-tool = В точке инструмента ({ $unit })
tool-point-outcome = В точке инструмента

## Axis report: uncertainty
uncertainty-heading = Неопределённость измерения (GUM, k = 2)
uncertainty-intro = Бюджет на длине измерения ({ $length }): суммарная стандартная неопределённость u{ $c } = { $combined } { $unit }, расширенная неопределённость U = 2u{ $c } = { $expanded } { $unit }. U каждого параметра в таблице результатов — бюджет на охватываемой им длине со статистикой его собственных оценок.
col-contributor = Составляющая
col-distribution = Распределение
col-share = Доля
check-model-empty = Нет проверок модели.
check-model-band-key = смоделированная 95 % полоса (базовая модель)
check-model-band-head = смоделированная 95 % полоса
check-model-band-head-narrow = 95 % полоса
check-model-measured = измерено
check-model-outside = измерено, проверка вне полосы
check-model-scale = у каждой статистики своя шкала
check-decision-empty = Нет нормируемых параметров.
check-decision-band-key = допуск ± U: зона неопределённости (ISO 14253-1)
check-decision-band-head = допуск − U … допуск + U
check-decision-band-head-narrow = допуск ± U
check-decision-value = значение
check-decision-outside = значение, несоответствие доказано
check-decision-scale = у каждого параметра своя шкала
check-beyond = за пределами шкалы
contributor-air-humidity = влажность воздуха
contributor-air-pressure = давление воздуха
contributor-air-temperature = температура воздуха
contributor-calibration = калибровка
contributor-dead-path = мёртвый ход луча
contributor-expansion-coefficient = коэффициент расширения
contributor-instrument-repeatability = повторяемость прибора
contributor-material-temperature = температура материала
contributor-mean-of-n = среднее из n
contributor-misalignment = несоосность
contributor-resolution = разрешение
contributor-s-of-n = S из n
contributor-temperature-change = изменение температуры
contributor-uncorrected-expansion = нескорректированное расширение
contributor-repeatability = повторяемость
contributor-optics = оптика
distribution-normal = нормальное
distribution-rectangular = равномерное
distribution-u-shaped = арксинусное
decision-heading = Значение и допуск ± U (зоны решения ISO 14253-1)

## Axis report: test-plan findings
findings-heading = Проверка программы испытаний
findings-none = Испытание следует программе стандарта: ни одно правило не нарушено.
col-severity = Важность
col-rule = Правило
col-clause = Пункт
col-finding = Замечание
severity-error = ошибка
severity-warning = предупреждение

## Axis report: model check and diagnosis
diagnosis-heading = Проверка модели и диагностика
diagnosis-intro = Параметры стандарта предполагают не названную в нём модель: систематическое отклонение в каждом положении и направлении, одну зону нечувствительности и белый разброс с одним σ, не зависящим от времени. axcheck подбирает эту модель, моделирует по ней испытания с программой данного испытания и называет то, что измерение показывает сверх неё.
diagnosis-verdict = Заключение проверки модели:
col-effect = Эффект
col-finding-evidence = Замечание, оценка и доказательство
evidence = Доказательство: { $evidence }
what-to-do = Что делать:
detectable-heading = Что эта программа может подтвердить
detectable-note = (величина, выявляемая в 80 % испытаний с этой программой):
unconfirmed-heading = Видно в испытании, не подтверждено прогнозом:
unconfirmed-note = его член даёт на отложенных данных не больше, чем посторонние члены того же размера, поэтому это не замечание, и расширенная модель его не включает.
held-out = Ошибка на отложенных данных ({ $validation }): базовая модель { $base } { $unit } СКЗ, расширенная модель { $extended } { $unit } СКЗ, выигрыш { $gain } %.
term-gains = По членам, при схеме отложенных данных, которая может его показать: { $list }.
model-terms = Базовые члены: { $base }. Расширенные члены: { $extended }.
out-of-test = Вне испытания: прогноз по { $from } этой оси ({ $readings } отсчётов в её ходе, после смещения нуля { $offset } { $unit }): базовая модель (гладкое систематическое отклонение) { $base } { $unit } СКЗ, расширенная модель (отклонение в заданных положениях и оставленные члены) { $extended } { $unit } СКЗ; { $intest }. Члены времени не учитываются: они начинаются заново с каждым испытанием.
col-parameter-unit = Параметр ({ $unit })
as-measured = измерено
without = без { $what }
checks-heading = Проверка модели: измеренные статистики и испытания, смоделированные по базовой модели
time-effect-heading = Эффект во времени относительно средних серий и остатки после него
residuals-time-heading = Остатки во времени
residuals-position-heading = Остатки вдоль оси
periodogram-heading = Периодограмма систематического отклонения вдоль оси (Ломб–Скаргл)

## Axis report: compensation table
compensation-heading = Таблица коррекции (система ЧПУ { $controller })
compensation-refused = Таблица не записана: { $reason }.
compensation-parameters-heading = Параметры измеренные и прогнозируемые с включённой таблицей
col-unit = Ед.
col-measured = Измерено
col-predicted = Прогноз
compensation-predicted-note = Прогноз: отсчёты этого испытания с таблицей, применённой так, как её хранит система ЧПУ (значения округлены до её единицы, { $applied }), вместо коррекции, включённой при испытании, обработанные заново.
compensation-chart-heading = Средние отклонения от заданного положения: измеренные и с таблицей
compensation-warnings-heading = Когда не следует корректировать
verification-heading = Проверка: это испытание повторно измеряет таблицу, загруженную после предыдущего измерения
verification-error = Проверку выполнить нельзя: { $error }.
verification-verdict = Заключение: { $verdict }.
verification-note = Прогноз: предыдущее измерение с коррекцией таблицы вместо действовавшей тогда. Заключение сравнивает достигнутое E (ISO 230-2, 2.20) с прогнозируемым и с прежним, каждую разность — с неопределённостью, которую допускает разброс двух измерений. { $notes }

## Axis report: inspection history
history-heading = История проверок ({ $count } проверок, { $first } — { $last })
history-first = Это первая проверка оси в истории: для тренда нужно две или больше.
history-flagged = отмечено { $flagged } из { $total } параметров
history-flagged-within = { $flagged } в пределах горизонта { $years } лет.
history-none-flagged = В пределах горизонта { $years } лет ни один параметр не отмечен.
closing-note = Составлено { $generator } по данным проверки; значения в { $unit }, положения как измерены.

## Campaign summary (summary.typ)
summary-title = сводка
summary-kind = Сводка проверки точности позиционирования
summary-site = Площадка
summary-purpose = Цель проверки
summary-date = Дата
summary-campaign-file = Файл проверки
summary-tests = испытаний
summary-trends-heading = Тренды по истории проверок ({ $first } — { $last })
summary-trends-none = Ни один из { $series } рядов этих осей не отмечен в пределах горизонта { $years } лет.
summary-trends-flagged = Отмечено { $flagged } из { $series } рядов этих осей в пределах горизонта { $years } лет (их показывает раздел «История проверок» протокола каждой оси):
summary-machine-axis = Станок, ось
summary-why = Почему
summary-axes-heading = Оси (значения в единицах оси; сначала требующие внимания)
summary-travel = Длина
summary-worst = Доля допуска
summary-diagnosis = Диагноз
summary-verdict = Итог
summary-no-tolerance = нет допуска
summary-axes-note = A, E, R, B по ISO 230-2 (R и B — это R_max и B_max для осей по ГОСТ 27843); «–»: не применяется (n = 1, п. 5.2) или не рассчитано. «Доля допуска»: параметр, занимающий наибольшую долю своего допуска. «Диагноз»: эффекты сверх модели стандарта, названные проверкой модели (нет: модель объясняет данные).
chart-usage-axis = Параметр с наибольшей долей / допуск
chart-usage-empty = Нет осей для сводки.
chart-usage-within = в пределах допуска
chart-usage-over = сверх допуска
chart-usage-limit = допуск
chart-usage-clipped = ▶ доля больше { $ratio }, полоса обрезана
summary-usage-heading = Использованная доля допуска (наибольшая для каждой оси)
summary-noncompliant-heading = Испытания не по программе
summary-errors-heading = Ошибки
summary-inputs-heading = Исходные данные
summary-inputs-intro = Составлено axcheck { $version } по { $total } файлам ниже командой { $command } (и папкой результатов); { $reproduce } на этой папке проверяет SHA-256 каждого файла, повторяет расчёт и побайтно сравнивает результаты.
summary-file = Файл
summary-sha = SHA-256 (первые 16 цифр)
summary-more-files = … и ещё { $more } файлов.
summary-paths-note = Пути относительно папки файла проверки (шаблоны и история — относительно заданной папки); results.json перечисляет все исходные файлы с полными SHA-256.
summary-closing-note = Составлено { $generator }. Протоколы осей: reports/MACHINE/AXIS.pdf.

## summary.html (page.js)
html-title = { $name } — сводка axcheck
html-search = Поиск
html-search-placeholder = станок, ось, заключение, правило, эффект …
html-keys = ↑ ↓ перемещение, Enter открывает, Esc закрывает
html-counts-label = Показать испытания с одним заключением
html-headline-title = { $symbol } с расширенной неопределённостью U (k = 2), в единицах строки
html-worst-title = Параметр, занимающий наибольшую долю своего допуска: |значение| / допуск
html-decision-rule = Правило решения
html-plan-rules = Правила программы
html-plan-rules-title = Нарушенные правила программы испытаний (не по программе); предупреждения — в подробностях
html-none = нет
html-compensation-e = Коррекция E
html-compensation-e-title = E измеренное → прогнозируемое с новой таблицей
html-trend = Тренд
html-trend-title = Параметры, тренд которых по истории проверок отмечен
html-flagged = отмечено: { $list }
verdict-error-word = Ошибка
html-footer = { $generator }. Значения в мкм (линейные оси) или угл. с (поворотные оси), 2 знака после запятой; U — расширенная неопределённость (k = 2).
html-inputs = Исходные данные: { $total } файлов, составлено axcheck { $version } командой { $command }
html-more-inputs = … и ещё { $more } (results.json перечисляет все)
html-close = Закрыть
html-limits = Допуски
html-axis-report = Протокол оси (PDF)
html-compensation-table = Таблица коррекции
html-value-unit = Значение / { $unit }
html-u-unit = U (k = 2) / { $unit }
html-limit-unit = Допуск / { $unit }
html-check = Проверка
html-outcome-pass = годен
html-outcome-fail = не годен
html-outcome-inconclusive = не определён
html-parameters = Параметры
html-not-applicable = Здесь не применяются: { $list }
html-rules = Правила программы испытаний
html-advice = Совет: { $advice }
html-no-effect = Эффектов сверх модели погрешностей не найдено.
html-controller = Система ЧПУ { $controller }, таблица { $mode }
html-built-on = , построена на { $file }
html-compensation-line = E { $text } { $unit } (измерено → прогноз)
html-not-written = Не записана: { $reason }
html-warning = Предупреждение: { $warning }
html-compensation = Коррекция
html-verification = Проверка
html-history = История
html-detail-unreadable = Подробности нельзя прочитать в этом браузере: { $error }
html-chart-bidirectional = Отклонения от заданного положения при двустороннем позиционировании (как ISO 230-2, рис. 2a)
html-chart-unidirectional = Отклонения от заданного положения при одностороннем позиционировании (как ISO 230-2, рис. 2b)
html-chart-history = История: { $label }

## Other laser tests (other-report.typ)
other-kind-straightness = Протокол проверки прямолинейности (ISO 230-1)
other-kind-angular = Протокол проверки угловых отклонений (ISO 230-1)
other-kind-squareness = Протокол проверки перпендикулярности (ISO 230-1)
other-from-to = от { $from } до { $to }
other-from-straightness = По проверкам прямолинейности
other-runs = Серий в каждом направлении
other-targets = Заданных положений
other-tolerance = Допуск
other-none-stated = не указан
other-chart-position = Заданное положение / { $unit }
other-chart-deviation = Отклонение от прямой ({ $line }) / { $unit }
other-chart-angular = Среднее угловое отклонение / { $unit }
other-outcome = Итог
other-cross-heading = Межосевая коррекция
other-uncertainty-heading = Неопределённость измерения (GUM)

## Inspection trends (trends.typ)
trends-kind = Тренды проверок
trends-dates = { $count } дат, { $first } — { $last }
trends-series = Ряды
trends-series-value = { $count } (станок, ось, параметр)
trends-flagged = Отмечено
trends-flagged-value = { $series } рядов на { $axes } осях
trends-horizon = Горизонт
trends-horizon-value = { $years } лет после последней проверки
trends-charts-note = На графиках: проверки (точки), прямая через них (сплошная) и до горизонта (штриховая), её полоса, допуск (красный), последняя проверка (серая штриховая) и в пределах горизонта место, где прямая достигает допуска (красный ромб).
trends-further-axes = ещё { $count } осей
trends-omitted = { $axes } ({ $flagged }) здесь не показаны: все ряды — в { $table }.
trends-omitted-flagged = из них отмечено { $count }
trends-omitted-none = ни одна не отмечена
trends-serial = (зав. № { $serial })
trends-axis = ось { $axis }
trends-closing-note = Составлено axcheck по истории { $history }. Все ряды с их числами: { $table }.

## Названия параметров ГОСТ 27843-88, раздел 1 (1.10–1.16), дословно
param-gost-A = точность позиционирования, двустороннего
param-gost-A_up = точность позиционирования, одностороннего ↑
param-gost-A_down = точность позиционирования, одностороннего ↓
param-gost-R_max = повторяемость двустороннего позиционирования
param-gost-R_up = повторяемость одностороннего позиционирования ↑
param-gost-R_down = повторяемость одностороннего позиционирования ↓
param-gost-R_mean = средняя повторяемость двустороннего позиционирования
param-gost-B_max = максимальная зона нечувствительности
param-gost-B_mean = средняя зона нечувствительности
## Параметры ISO 230-2 (ГОСТ ISO 230-2-2016 недоступен целиком): термины ГОСТ 27843-88,
## E и M — по определениям ISO 230-2 2.19–2.21
param-iso-A = точность двустороннего позиционирования
param-iso-A_up = точность одностороннего позиционирования ↑
param-iso-A_down = точность одностороннего позиционирования ↓
param-iso-E = двустороннее систематическое отклонение позиционирования
param-iso-E_up = одностороннее систематическое отклонение ↑
param-iso-E_down = одностороннее систематическое отклонение ↓
param-iso-M = размах средних двусторонних отклонений
param-iso-R = повторяемость двустороннего позиционирования
param-iso-R_up = повторяемость одностороннего позиционирования ↑
param-iso-R_down = повторяемость одностороннего позиционирования ↓
param-iso-B = зона нечувствительности
param-iso-B_mean = средняя зона нечувствительности

## Certificate of a calibration laboratory (certificate.typ; ISO/IEC 17025:2017 7.8)
cert-title = Сертификат о калибровке
cert-number = № { $number }
cert-customer = Заказчик
cert-laboratory = Лаборатория
cert-date-measured = Дата измерений
cert-date-issued = Дата выдачи
cert-place = Место проведения
cert-method = Методика
cert-deviations = Отступления от методики
cert-deviations-none = нет
cert-traceability-heading = Прослеживаемость средств измерений
cert-col-instrument = Средство измерений
cert-col-serial = Заводской номер
cert-col-certificate = Сертификат о калибровке
cert-col-calibrated = Дата калибровки
cert-col-due = Действителен до
cert-col-body = Кем откалибровано
cert-not-stated = не указано
cert-statement = Результаты прослеживаются к единице длины SI — метру — через калибровку перечисленных средств измерений, действительную на дату измерений. Результаты относятся только к откалиброванному объекту. Частичное воспроизведение сертификата без письменного разрешения лаборатории не допускается.
cert-authorised-by = Утвердил
cert-signature = Подпись, дата выдачи { $date }
method-straightness = ISO 230-1:2012 (прямолинейность)
method-angular = ISO 230-1:2012 (угловое отклонение)
method-squareness = ISO 230-1:2012 (перпендикулярность)
as-found-heading = До и после регулировки (значения в { $unit })
as-found-intro = Ось отрегулирована между двумя измерениями: до регулировки ({ $found }) — { $found_verdict }; после регулировки ({ $left }) — { $left_verdict }. Оба результата оценены по одним и тем же допускам и одному правилу принятия решения.
col-as-found = До регулировки
col-as-left = После регулировки

## Conditions' values (conditions.rs)
unit-mm-per-min = мм/мин
unit-deg-per-min = °/мин
unit-kpa = кПа
unit-rh = { $value } % отн. влажн.
nde-alpha = ; α = { $alpha } мкм/(м·°C)
nde-applied = приведено axcheck к 20 °C: α = { $alpha } мкм/(м·°C), средняя температура { $mean } °C по { $source }; наибольшая поправка { $max } мкм
nde-in-data = да, в данных (средством измерений){ $alpha }
nde-not-applied = не введена (температура не задана){ $alpha }
sensor-kind-material = материал
sensor-kind-air = воздух

## What a test was judged by (axis.rs spec_words)
spec-no-tolerance = допуски не заданы
spec-plus-axis = { $spec } + допуски оси
spec-axis-tolerances = допуски оси
spec-example = { $spec } — примерные допуски, не из стандарта

## A verdict's uncertainty, large (axis.rs large_uncertainty)
large-u = { $symbol } = { $value } ± { $u } { $unit } при допуске { $limit } { $unit }: { $why }
large-u-why-both = U больше половины допуска и больше значения
large-u-why-half = U больше половины допуска
large-u-why-value = U больше значения

## An instrument with its serial number; the purposes of a test (ISO 230-2 clause 1)
instrument-serial = { $name }, зав. № { $serial }
purpose-periodic = периодическая
purpose-acceptance = приёмочная
purpose-comparison = сравнительная
purpose-type = типовая
purpose-compensation = для коррекции

## Standards' titles in this language (Words::standard; the others as axcheck writes them)
standard-gost27843 = ГОСТ 27843-88
standard-gbt17421-2 = GB/T 17421.2-2000 (эквивалентен ISO 230-2:1997, с изменением № 1)

## summary.html's count of the rows shown (page.js)
html-shown-count = показано { $shown } из { $total } проверок

## The diagnosis's residual charts and periodogram (data/diagnosis.rs, charts/diagnosis)
diag-x-time = Время от начала проверки / мин
diag-x-order = Отсчёты в порядке цикла проверки
diag-y-residual = Остаток базовой модели / { $unit }
diag-period = Период / { $unit }
diag-residual-up = остаток ↑
diag-residual-down = остаток ↓
diag-band = базовая модель ±2σ (±{ $value })

## The model check's statistics (data/diagnosis.rs; diagnose::checks names them)
check-run-mean-spread = разброс средних по прогонам
check-lag1-autocorrelation = автокорреляция с лагом 1
check-max-studentized-residual = наибольший стьюдентизированный остаток
check-reversal-range = размах зоны нечувствительности
check-scatter-ratio-end-to-start = отношение рассеяния конец/начало
check-periodogram-max-f = наибольшее F периодограммы
check-trend-lack-of-fit-rms = СКО неадекватности тренда
