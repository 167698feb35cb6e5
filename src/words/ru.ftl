# Слова zsim по-русски, в терминах учебника (Роджерс в русском переводе):
# пиксел, буфер кадра, z-буфер, многоугольник, сканирующая строка.

buffer-frame = буфер кадра
buffer-depth = z-буфер
polygon-name = { $named ->
    [yes] многоугольник { $number } «{ $name }»
   *[no] многоугольник { $number }
}
polygon-after = { $named ->
    [yes] многоугольника { $number } «{ $name }»
   *[no] многоугольника { $number }
}
span = { $left } … { $right }
scanline = y = { $y }
list-and = { " и " }
list-semicolon = { "; " }
# Decimals take the comma, so lists of numbers take semicolons.
list-comma = { "; " }

winding-cw = по часовой стрелке
winding-ccw = против часовой стрелки

stored-whole = в z-буфер записывается { $stored }
stored-rounded-up = в z-буфер записывается { $stored } ({ $value } округляется вверх до { $stored })
stored-rounded = в z-буфер записывается { $stored } ({ $value } округляется до { $stored })
stored-saturated = в z-буфер записывается { $stored } ({ $value } округляется до { $rounded } и ограничивается значением { $stored })
stored-exact = в z-буфер записывается { $stored } (точно)

z-w-buffer = { $w } (глубина в системе координат наблюдателя для w-буфера; после проецирования z' = { $z })
z-projected = { $z } (z' после проецирования; глубина в системе координат наблюдателя w = { $w })
z-beyond = (за пределами 128-битной точной арифметики)

test-passed = { $z } { $op } { $stored }
test-failed = { $z }, условие z { $op } { $stored } не выполняется
test-uncompared = { $z } (тест глубины { $test }; в z-буфере было { $stored })
rule-compared = z { $op } значения в z-буфере
rule-always = проходит любой фрагмент
rule-never = не проходит ни один фрагмент

frame-blended = { $frame } (непрозрачность { $alpha }: { $alpha }·{ $value } + { $rest }·{ $under } под ним, половина округляется вверх)
reason-written = z = { $test }, поэтому { $stored }, а в буфер кадра — { $frame }
reason-hidden = z = { $test }: пиксел скрыт, ничего не меняется
reason-outside-range = z = { $z } вне диапазона глубины { $front } … { $rear }: фрагмент отбрасывается
reason-beyond-section = z = { $test }, но сечение оставляет только z { $op } { $section }: не записывается

fate-culled = отбрасывается как нелицевой: его вершины обходятся { $winding }, поэтому он не рисуется
fate-edge-on = виден с ребра (c = 0): не покрывает ни одного пиксела
fate-degenerate = вырожден (нормаль по Ньюэлу нулевая): не покрывает ни одного пиксела
fate-clipped = все вершины лежат за ближней плоскостью: отсекается целиком и не рисуется

entry-no-row = его диапазон по y не достигает сканирующей строки { $scanline }{ $tie }
entry-covered = на сканирующей строке { $scanline } он занимает отрезок { $span }, в котором лежит центр x = { $centre }{ $tie }; { $reason }
entry-covered-no-span = на сканирующей строке { $scanline } он покрывает центр x = { $centre }{ $tie }; { $reason }
entry-not-inside = на сканирующей строке { $scanline } { $spans }; центр x = { $centre } не попадает внутрь{ $tie }
spans-none = { $subject } не пересекает строку
spans-some = { $subject } занимает { $spans }
subject-it = он
tie-wrap = { " (" }{ $text })

why-covers = { $polygon } покрывает ({ $x }, { $y }): z = { $test }, поэтому { $result }
why-later = { "; затем " }{ $list }
why-later-item = { $polygon } ({ $reason })
result-frame = в буфере кадра { $value }
cleared-frame = фон { $value }
cleared-depth = начальная глубина { $value }
why-covered-item = { $polygon } покрывает его, но { $reason }
why-nothing-written = в ({ $x }, { $y }) ничего не записано: { $list }; там остаётся { $cleared }
why-none-reaches = ни один многоугольник не покрывает ({ $x }, { $y }): ни один не достигает сканирующей строки { $scanline }; там остаётся { $cleared }
why-not-covered = ни один многоугольник не покрывает ({ $x }, { $y }): на сканирующей строке { $scanline } { $list }; там остаётся { $cleared }

boundary-top = верхнем ребре
boundary-bottom = нижнем ребре
boundary-left = левом ребре
boundary-right = правом ребре
boundary-vertex = вершине
tie-vertex = центр совпадает с вершиной { $point }: решают сходящиеся в ней рёбра по правилу: { $rule }
tie-edge-in = центр лежит точно на { $boundary } от { $a } до { $b }, и { $rule } его включает
tie-edge-out = центр лежит точно на { $boundary } от { $a } до { $b }, и { $rule } его исключает
rule-columns-centre = правило книги для столбцов (центры в [x_l, x_r], концы включены)
rule-columns-cell = правило BUET для столбцов (от ячейки с x_a до ячейки с x_b)
rule-columns-half-open = правило полуоткрытых столбцов (центры в [x_l, x_r): левые рёбра включаются, правые нет)
rule-rows-half-open = правило полуинтервала из книги (ребро учитывается при min ≤ y < max)
rule-rows-closed = замкнутые строки BUET (min ≤ y ≤ max)
rule-rows-top-left = правило «верх-лево» (ребро учитывается при min < y ≤ max: верхние рёбра включаются, нижние нет)

explain-heading = пиксел ({ $x }, { $y }) сцены { $file }: центр ({ $cx }; { $cy }), тест глубины { $test } ({ $rule })
polygon-line = { $polygon }: { $text }
explain-start = начало: буфер кадра { $frame }, z-буфер { $depth } (после очистки)
explain-final = итог: буфер кадра { $frame }, z-буфер { $depth }

check-all-match = { $buffer } { $file }: совпадает с верным ответом после { $after } (ячеек: { $cells })
check-differ = { $buffer } { $file }: { $count ->
    [one] отличается { $count } ячейка
    [few] отличаются { $count } ячейки
   *[many] отличаются { $count } ячеек
  } из { $cells } после { $after }
check-unanswered = ; без ответа (? или .) { $count ->
    [one] оставлена { $count } ячейка
    [few] оставлены { $count } ячейки
   *[many] оставлено { $count } ячеек
  } из { $cells }
check-hint-matches = подсказка: если читать { $how }, ответ совпадает; записывайте сначала верхнюю строку (y = { $top }), каждую строку от x = 0, как в книге
check-hint-fewer = подсказка: если читать { $how }, расхождений остаётся: { $left }; записывайте сначала верхнюю строку (y = { $top }), каждую строку от x = 0, как в книге
check-column-answer = ответ
check-column-right = верно
check-column-why = почему
check-in-arith = в арифметике { $arith } в ячейке { $mode }; в точной арифметике { $exact }: { $reason }
grade-summary = класс { $class }, сцена { $scene }, после { $polygon }: { $students ->
    [one] { $students } студент
    [few] { $students } студента
   *[many] { $students } студентов
  }; верно: { $ok }, с ошибками: { $wrong }, с негодными файлами: { $malformed }, без ответа: { $missing }
grade-column-student = студент
grade-column-frame = ошибок в буфере кадра
grade-column-depth = ошибок в z-буфере
grade-column-score = баллы, %
grade-column-status = итог
grade-column-buffer = буфер
grade-column-wrong = ошиблись
grade-column-answered = ответы
grade-status-ok = верно
grade-status-wrong = с ошибками
grade-status-incomplete = не закончено: { $count ->
    [one] { $count } ячейка оставлена
    [few] { $count } ячейки оставлены
   *[many] { $count } ячеек оставлено
  } без ответа
grade-status-malformed = негодный файл: { $why }
grade-status-missing = нет файла: { $what }
grade-students-of = { $count } из { $total }
grade-mistakes = частые ошибки (ячейки, в которых ошиблись хотя бы двое, сначала самые частые):
grade-mistakes-none = частые ошибки: ни в одной ячейке не ошиблись двое или больше
grade-feedback = { $student }: { $scene }, после { $polygon }: { $score } %, { $status }
exercise-title = упражнение, seed { $seed }: растр { $width }×{ $height }, { $count ->
    [one] { $count } многоугольник
    [few] { $count } многоугольника
   *[many] { $count } многоугольников
  }
exercise-solution-title = упражнение, seed { $seed }: буфер кадра после последнего многоугольника
exercise-task-draw = Нарисуйте многоугольники по порядку (сначала A) алгоритмом z-буфера: чем больше z, тем ближе; z-буфер вначале заполнен нулями и хранит 0 … { $max } (с округлением и насыщением).
exercise-task-write = Запишите буфер кадра (значение каждого многоугольника) и z-буфер после последнего многоугольника, начиная с верхней строки.
misreading-upside-down = с нижней строки
misreading-transposed = по столбцам (строки и столбцы переставлены)

## run и step: заголовок сцены, этапы, заголовок многоугольника

depth-test-greater = больше
depth-test-less = меньше
depth-test-greater-equal = больше или равно
depth-test-less-equal = меньше или равно
depth-test-always = всегда
depth-test-never = никогда
scene-header = сцена { $path }: { $width }×{ $height } пикселов, буфер кадра { $frame_bits } бит, z-буфер { $depth_bits } бит (0…{ $depth_max }), тест глубины { $test } ({ $rule }), после очистки { $clear }
scene-stages = этапы: { $stages }
scene-effects = эффекты: { $effects }
effects-none = нет
stage-cull = отбрасывание нелицевых граней (пропускаются многоугольники с обходом { $winding })
stage-near-plane = отсечение ближней плоскостью (остаётся z ≤ { $near }) и перспективная проекция (глаз в z = { $eye })
stage-supersampling-sample = суперсэмплинг { $k }×{ $k } (глубина в каждом отсчёте), затем усреднение
stage-supersampling-pixel = суперсэмплинг { $k }×{ $k } (глубина в центре пиксела), затем усреднение
stage-window = окно { $left } … { $right } × { $bottom } … { $top } на растр
stage-scan = разложение в растр
stage-scan-closed = разложение в растр (замкнутые строки, ячейки с пересечениями)
stage-scan-top-left = разложение в растр (правило «верх-лево»)
stage-depth-range = диапазон глубины (отбрасываются z вне { $front } … { $rear })
stage-w-buffer = w-буфер (глубина в системе наблюдателя z = d·z'/(d + z'))
stage-depth-test = тест глубины ({ $rule })
stage-section = сечение (z { $op } { $section })
stage-blend = смешивание по непрозрачности (α·значение + (1 − α)·нижнее, половина округляется вверх)
stage-store-quantized = запись (половина округляется вверх, ограничение 0…{ $max })
stage-store-exact = запись (точная глубина)
heading-start = { $polygon } (значение { $value })
heading-degenerate = { $start }: вырожден: нормаль по Ньюэлу нулевая (вершины на одной прямой или взаимно гасящиеся петли), поэтому у него нет плоскости и он не покрывает ни одного пиксела
heading-clipped-away = { $start }: за ближней плоскостью: отсекается целиком, не рисуется
heading-edge-on = { $start }: плоскость { $plane }: виден с ребра (c = 0), не покрывает ни одного пиксела
heading-culled = { $start }: плоскость { $plane }, { $winding }: отбрасывается как нелицевой (cull { $cull }), не рисуется
heading-drawn = { $start }: плоскость { $plane }{ $winding }{ $opacity }{ $clipped }
heading-drawn-projected = { $start }: плоскость после проецирования { $plane }{ $winding }{ $opacity }{ $clipped }
heading-winding = { ", обход " }{ $winding }
heading-opacity = { ", непрозрачность " }{ $alpha }
heading-clipped = { "; " }перед ближней плоскостью { $front } из { $of } вершин, рисуется как { $n }-угольник
run-counts = покрыто центров пикселов: { $covered }, записано: { $written }
run-frame-after = буфер кадра после { $polygon }:
run-depth-after = z-буфер после { $polygon }:
run-no-polygons = в сцене нет многоугольников: буферы остаются такими, как после очистки
run-frame-cleared = буфер кадра после очистки:
run-depth-cleared = z-буфер после очистки:
figure-title-worksheet = { $file }: многоугольники, которые надо нарисовать, на пустом растре
figure-title-after = { $file }: { $buffer } после { $polygon }
figure-title-samples = { ", " }по { $k }×{ $k } выборок на пиксел до усреднения (средние даёт `zsim run`)
figure-cell = ({ $x }, { $y }): буфер кадра { $frame }, z-буфер { $depth }
figure-cells = ({ $from } … { $to }, { $y }): буфер кадра { $frame }
figure-background = { $value }: фон
figure-value = значение { $value }
figure-value-named = значение { $value }: { $names }
figure-polygons = многоугольников: { $count }
figure-axis-x = x (числа стоят у центров пикселов, x + ½)
figure-cleared = после очистки ({ $value })
figure-far = { $larger_nearer ->
    [yes] меньше z: дальше
   *[no] больше z: дальше
}
figure-near = { $larger_nearer ->
    [yes] больше z: ближе
   *[no] меньше z: ближе
}
file-written-about = записан { $path } ({ $about })
file-written-page = записан { $path } (откройте его в браузере; сеть не нужна)

## step по строкам

step-slope = вдоль сканирующей строки z меняется на −a/c = { $slope }
step-scanline = сканирующая строка { $scanline } (строка растра { $row })
step-crossings = пересечения: { $list }
step-crossings-none = нет
step-span = отрезок { $n }: x_a = { $xa }, z_a = { $za }; x_b = { $xb }, z_b = { $zb }; { $columns }
step-columns = столбцы { $first } … { $last }
step-no-column = ни одного столбца
step-col-centre = центр
step-col-step = шаг
step-col-stored = в z-буфере
step-col-test = тест
step-col-after = после
step-col-frame = кадр
step-start = начало
step-written = { $test }: записано
step-hidden = { $test }: скрыт
step-test-written = { $z } { $op } { $stored }: записано
step-test-hidden = { $z } { $op } { $stored }: нет, скрыт
step-beyond-section = { $op } { $stored }, за сечением
step-outside-range = { $z }: вне диапазона глубины, отброшено
step-tie = граничный случай при x = { $x }: { $text }
step-frame-after = буфер кадра после этой строки (строки { $low } … { $high }):
step-depth-after = z-буфер после этой строки (строки { $low } … { $high }):
step-end = конец сцены: строк больше нет (b назад, q выход)
step-first = это уже первая строка
step-outside-raster = строка { $row } вне растра (строки 0 … { $last })
step-not-reach = { $polygon } не достигает сканирующей строки { $scanline }
step-unknown = неизвестная команда «{ $text }»; { $help }
step-prompt = { "zsim step> " }

## step в терминале: полноэкранный режим

tui-title = zsim step ·{ $heading } · { $view }{ $score } · ? клавиши
tui-heading = { " " }{ $polygon }, сканирующая строка { $scanline }
tui-heading-end = { " конец сцены" }
tui-score = { " · опрос " }{ $right }/{ $asked }
tui-key-nothing = эта клавиша здесь ничего не делает: ? покажет клавиши
tui-no-later = ни один следующий многоугольник не покрывает пикселов
tui-no-earlier = ни один предыдущий многоугольник не покрывает пикселов
tui-go = перейти к сканирующей строке ряда: { $text }▏ (Enter — перейти, Esc — отмена)
tui-status = n/→ дальше · b/← назад · p/P многоугольник · g перейти · f/z буфер · m по пикселам · q выход
tui-no-scanline = нет сканирующей строки
tui-columns-shown = x { $first } … { $last } из 0 … { $max }
tui-end = конец сцены
tui-span = отрезок { $n }: { $left } … { $right }; { $columns }
tui-no-centre = ни одного центра
tui-table-heading = x { $z } тест → в z-буфер (кадр)
tui-uncompared = { $test } пропускает,{ " " }
tui-not = { "не " }
tui-hidden = скрыт
tui-pixel-by-pixel = m: по пикселам, с объяснениями
tui-steps-from = { ", " }шагов −a/c от { $start }: { $count }
tui-pixel = ({ $x }, { $y }): центр x = { $centre }, z = { $z }{ $steps }
tui-keys = { " клавиши " }
tui-help =
    n Space Enter → ↓  следующая строка (или пиксел)
    b ← ↑              назад
    p / P              следующий / предыдущий многоугольник
    g                  перейти к сканирующей строке ряда
    f / z              показать буфер кадра / z-буфер
    m                  по пикселам / по строкам
    PgUp PgDn < >      прокрутить растр
    { "[ ]" }                прокрутить таблицу
    ?                  эти клавиши (любая клавиша закрывает)
    q Esc Ctrl-C       выход

    жёлтым: покрытые пикселы отрезка
    голубым: прежние записи этого многоугольника

## опрос (step --quiz)

quiz-mistakes = ваши ошибки:
meant-not-written = не записывается
meant-value-written = записанное значение
meant-value-kept = не записывается: значение, которое остаётся
meant-value = значение
quiz-coverage-hint = введите покрытые столбцы как первый-последний (несколько отрезков через пробел: 3-5 9-12) или -, если ни одного
quiz-coverage-why = отрезки: { $spans }; столбец покрыт, если его центр x + 1/2 лежит в одном из них
quiz-coverage-mistake = строка { $row } { $polygon }: ваш ответ — столбцы { $said }, верно { $right }: { $why }
quiz-depth-hint = введите значение, которое будет в z-буфере, или - если не записывается (q завершает опрос)
quiz-not-an-answer = «{ $text }» — не ответ: { $hint }
quiz-does-not-fit = { $text } не помещается в этот z-буфер: его ячейки хранят целые уровни 0 … { $max }; введите снова
quiz-keeps = - (остаётся { $value })
quiz-depth-mistake = ({ $x }, { $y }) { $polygon }: ваш ответ { $said }, верно { $right }: { $reason }

## step --html: страница

page-back = ◀ Назад (b)
page-next = Дальше ▶ (n)
page-previous-polygon = ◀◀ Многоугольник (P)
page-next-polygon = Многоугольник ▶▶ (p)
page-frame = Буфер кадра (f)
page-depth = Z-буфер (z)
page-quiz = опрос
page-no-pixel = Эта сцена не покрывает ни одного пиксела.
page-frame-after = буфер кадра после этой строки
page-depth-after = z-буфер после этой строки
page-column-stored = было
page-column-after = z-буфер после
page-column-why = почему
page-keeps = – (остаётся { $value })
page-check = Проверить ответы
page-status = строка { $at } из { $count }

## ошибки, которые чаще всего встречаются студенту: файлы, многоугольники, ответы

error-read = { $path }: не удаётся прочитать: { $reason }
error-write = { $path }: не удаётся записать: { $reason }
error-polygon = { $path }: { $polygon }: { $problem }
geometry-too-few = вершин { $count }; у многоугольника их должно быть не меньше 3
geometry-too-many = вершин { $count }; zsim принимает не больше { $max }
geometry-out-of-range = у вершины { $vertex } координата { $value } вне точного диапазона: при общем знаменателе многоугольника { $denominator } |координата| × 2 × { $denominator } должна быть не больше 2^4096 (возьмите координаты меньше или меньше знаков после запятой)
digits = { $count } цифр
geometry-off-plane-z = не плоский: вершина { $vertex } отстоит от плоскости { $plane }, проведённой через вершины { $i }, { $j }, { $k }, на Δz = { $off }
geometry-off-plane = не плоский: вершина { $vertex } даёт { $off } вместо 0 в уравнении плоскости { $plane }, проведённой через вершины { $i }, { $j }, { $k }
answer-at-cell = строка { $line }, число { $column } (x = { $x }, y = { $y })
answer-at = строка { $line }, число { $column }
answer-not-a-number = { $at }: «{ $cell }» — не целое число ({ $buffer } хранит 0 … { $max })
answer-too-large = { $at }: { $value } не помещается в { $buffer } (0 … { $max })
answer-row-length = строка { $line }: { $count ->
    [one] { $count } число
    [few] { $count } числа
   *[many] { $count } чисел
  }, а ширина растра { $width }
answer-row-count = строк { $count }, а у растра их { $height }
answer-frame-range = { $bits }-битный буфер кадра
answer-depth-range = { $bits }-битный z-буфер

## дополнения explain: сечение, сегменты, проверки «внутри», сглаживание, другая арифметика

explain-section = сечение: записываются только z { $op } { $section }
explain-inside = проверки «внутри» для центра: трассировка луча — { $ray }; сумма углов — { $arc }
explain-inside-in = внутри
explain-inside-out = снаружи
explain-arc-boundary = на границе, значит внутри
explain-arc-winding = число оборотов { $winding }, значит { $inside }
explain-segment = сегмент { $number } из { $count } ({ $segments }): столбцы { $first } … { $last }, строки { $bottom } … { $top }; его z-буфер хранит ячеек: { $cells }; его затрагивают: { $visited }
explain-segment-none = ни один многоугольник
explain-antialias = сглаживание по сетке отсчётов { $k }×{ $k } (строки выше — центр пиксела без сглаживания; строки отсчётов ведут счёт в 1/{ $k } пиксела)
explain-sample = отсчёт ({ $i }, { $j }) в точке ({ $x }; { $y }): буфер кадра { $frame }, z-буфер { $depth }
explain-pixel-mode = { $polygon } покрывает отсчёты { $samples }; глубина его плоскости в центре пиксела { $depth }: { $result }
explain-pixel-mode-written = записано, в z-буфере { $stored }, и эти отсчёты получают значение
explain-pixel-mode-not-written = не записано
explain-mean = среднее по отсчётам: буфер кадра { $frame }, z-буфер { $depth }
explain-arith = в арифметике { $arith }: буфер кадра { $frame }, z-буфер { $depth } ({ $verdict })
explain-arith-same = как в точной
explain-arith-differs = не то, что даёт точная арифметика

## вершины в пространстве отсечения [x, y, z, w]

vertex-decimal-comma = в вершине четыре числа, { $written }, среди вершин [x, y, z]: { $comma } — это десятичная запятая? В JSON дробную часть отделяет точка: напишите { $meant }
clip-space-mixed = смешивает вершины [x, y, z] с вершинами [x, y, z, w] в пространстве отсечения: запишите все вершины многоугольника одинаково
clip-space-alone = задан вершинами [x, y, z, w] в пространстве отсечения, которые переносит на растр преобразование области вывода; они не сочетаются с окном и с эффектом перспективы
fate-outside-view = он вне видимого объёма (−w ≤ x, y, z ≤ w): отсекается целиком и не рисуется
heading-outside-view = { $start }: вне видимого объёма (−w ≤ x, y, z ≤ w): отсекается целиком, не рисуется
heading-view = { "; пространство отсечения: " }внутри видимого объёма { $inside } из { $of } вершин, после отсечения, деления на w и области вывода рисуется как { $n }-угольник

## чтение сцены

scene-not-object = сцена — это JSON-объект вида {"{"}"width": 32, "height": 32, "polygons": [...]{"}"}, а не { $found }
json-array = массив
json-string = строка
json-number = число
json-bool = true или false
json-null = null
json-comma-end = { " (в конце строки " }{ $line } не хватает запятой)
json-comma-after = { " (не хватает запятой после строки " }{ $line }, позиции { $column })
json-invalid = это не корректный JSON: { $error }
location-polygon = многоугольник { $number }
number-found-object = ожидалось число, а найден объект
number-found-bool = ожидалось число, а найдено логическое значение
number-found-null = ожидалось число, а найдено null
number-found-list = ожидалось число, а найден список
number-not-a-number = «{ $text }» — не число (запишите целое, десятичную дробь вроде 2.5 или дробь вроде "5/2")
number-zero-denominator = «{ $text }» — деление на ноль
number-too-large = в «{ $text }» слишком много цифр, чтобы хранить точно (не больше 30 значащих цифр)
number-too-long = в «{ $text }» слишком много цифр или слишком большая степень десяти (у координаты вершины не больше { $max } значащих цифр и степени десяти не больше ±{ $max })
setting-bits = { $value } не поддерживается: допустимо от 1 до 32 бит
setting-side-zero = должно быть не меньше 1 пиксела
setting-side-large = { $side } больше предела в { $max } пикселов
setting-cells = { $width }×{ $height } — это { $cells } пикселов, больше предела { $max }
setting-background = { $value } не помещается в { $bits }-битный буфер кадра (не больше { $max })
setting-window = левая граница { $left } должна быть меньше правой { $right }, нижняя { $bottom } — меньше верхней { $top }
setting-depth-range = [{ $front }, { $rear }]: передняя граница не должна быть больше задней
setting-clear-depth = применяется только к точному z-буферу (правила с "store": "exact"); квантованный очищается до самого дальнего уровня
setting-perspective-positive = перспектива: distance и near должны быть положительными
setting-antialias-samples = сглаживание: { $samples } отсчётов не поддерживается: допустимо от 1 до 16
setting-antialias-cells = сглаживание: { $width }×{ $height } пикселов × { $samples }² отсчётов больше предела в { $max } ячеек
setting-antialias-exact = сглаживание усредняет квантованный z-буфер; с точным хранением оно не сочетается
polygon-opacity = непрозрачность { $alpha } вне диапазона 0 … 1
polygon-value-too-wide = значение { $value } не помещается в { $bits }-битный буфер кадра (не больше { $max })

origin-supersampled = сцена с суперсэмплингом { $factor }×
origin-snapped = сцена, привязанная к fixed:{ $bits }

usage-arith-plain-rules = --arith { $arith } моделирует простой алгоритм по правилам учебника; эта сцена требует других правил или попиксельных эффектов (используйте --arith exact)
usage-arith-greater-or-less = --arith { $arith } моделирует тесты глубины greater и less; эта сцена требует { $test } (используйте --arith exact)
usage-arith-plain-loop = --arith, отличный от exact, выполняет простой цикл z-буфера; уберите --segments и --order
usage-no-polygon-numbered = многоугольника { $number } нет: в сцене их { $count } (нумерация с 1)
usage-no-polygon-named = многоугольника с именем «{ $name }» нет: в сцене есть { $names }
usage-pixel-outside = пиксел ({ $x }, { $y }) лежит вне растра { $width }×{ $height } (x 0 … { $last_x }, y 0 … { $last_y })
usage-figure-format = { $path }: рисунок записывается как .svg, .png, .pdf или .tex (TikZ)
usage-figure-too-large = { $path }: рисунок строится для растров до { $max }×{ $max }; этот растр { $width }×{ $height }
usage-png-failed = { $path }: не удаётся построить рисунок: { $reason }
usage-no-polygons-draw = { $path }: в сцене нет многоугольников для рисования
usage-no-polygons-grade = { $path }: в сцене нет многоугольников для оценки
usage-no-polygons-check = { $path }: в сцене нет многоугольников для проверки
usage-exact-depths-grade = { $path }: эта сцена хранит точные глубины, поэтому у её z-буфера нет целочисленной матрицы для оценки; оценивайте буферы кадра
usage-exact-depths-check = { $path }: эта сцена хранит точные глубины, поэтому у её z-буфера нет целочисленной матрицы для проверки; проверьте буфер кадра или z_buffer.txt курса BUET командой `zsim buet check`
usage-check-needs-answer = для проверки нужен ответ: --frame ФАЙЛ и/или --depth ФАЙЛ
usage-no-answers = { $path }: ответы не найдены: назовите файлы каждого студента ИМЯ.frame.txt и/или ИМЯ.depth.txt
usage-scenes-range = --scenes принимает от 1 до 100
usage-memory-bits = { $option } { $bits }: допускается от 1 до 64 бит
usage-memory-zero = --width, --height и --supersample должны быть не меньше 1
usage-memory-too-large = растр слишком велик для подсчёта (больше 2^50 ячеек)
usage-random-count = --count { $count }: не более { $max } треугольников (сцену такого размера читать обратно около 10 ГБ)
usage-random-bits = --frame-bits и --depth-bits принимают от 1 до 32
usage-random-side = --width и --height принимают от 1 до { $max }
usage-not-a-hard-case = --hard: «{ $name }» — не трудный случай: { $names }
usage-exercise-size = --size { $width }x{ $height }: упражнение имеет от 4 до 64 пикселов по стороне
usage-exercise-polygons = --polygons { $count }: в упражнении от 1 до 8 многоугольников
usage-exercise-bits = для упражнения вручную --frame-bits принимает от 1 до 8, а --depth-bits от 1 до 16
usage-exercise-two-polygons = для hidden и intersecting нужны два многоугольника или больше (--polygons 2)
usage-exercise-not-found = за { $tries } попыток не нашлось сцены из { $polygons } многоугольников на растре { $width }×{ $height } со всеми случаями { $cases }; попросите меньше случаев, больше многоугольников или больший растр
usage-inside-needs-pixel-order = --inside выбирает тест «точка в многоугольнике» для --order pixels; добавьте --order pixels
usage-tiles-need-format-none = --tile и --threads относятся к --format none, --final и --after (иначе показывается состояние после каждого многоугольника, нарисованного по порядку)
usage-format-none-is-plain = --format none подводит итог цикла z-буфера; с --segments, --order pixels или сглаживанием используйте text или json
usage-no-scanlines = { $polygon } не имеет сканирующих строк: { $why }
usage-scanline-rows = { $reach }: его строки { $first } … { $last }
usage-scanline-no-rows = { $reach }: он не достигает ни одной строки растра

step-skip-fate = { $polygon }: { $why }
step-skip-no-scanline = { $polygon }: не достигает ни одной сканирующей строки растра
step-skip-no-centre = { $polygon }, сканирующая строка { $scanline }: не покрыт ни один центр пиксела
step-skip-no-centre-no-crossings = { $polygon }, сканирующая строка { $scanline }: не покрыт ни один центр пиксела (пересечений нет)

case-line = строка { $line }: { $problem }
case-unknown-command = неизвестная команда «{ $command }»
case-keyword-problem = { $keyword }: { $problem }
list-or = { $rest } или { $last }
cs418-second-png = вторая строка «png» (файл называет одно изображение, в первой строке)
cs418-before-png = «{ $keyword }» стоит до строки «png WIDTH HEIGHT FILE», которая должна быть первой
cs418-flag-numbers = «{ $keyword }» не принимает чисел, найдено { $found }
cs418-fsaa = fsaa { $level }: уровень должен быть от 1 до 8
cs418-size = { $keyword } { $size }: размер должен быть { $allowed }
cs418-not-an-index = elements: «{ $word }» — не индекс (целое число ≥ 0)
cs418-matrix = uniformMatrix нужны 16 чисел, найдено { $found }
cs418-count = { $keyword }: число { $count } не кратно 3
cs418-texture-name = texture нужно имя файла
cs418-texture = текстура «{ $name }»: { $why }
cs418-no-png = нет строки «png WIDTH HEIGHT FILE»: это файл CS 418?
cs418-png-words = png нужны WIDTH HEIGHT FILE, найдено слов: { $found }
cs418-png-side = png: { $what } «{ $word }» должно быть целым числом от 1 до { $max }
cs418-png-file = png: «{ $file }» должно быть простым именем файла, без папок
cs418-not-a-number = { $keyword }: «{ $word }» — не число
cs418-integers = { $keyword } нужно целых чисел: { $count }, найдено { $found }
cs418-not-a-whole-number = { $keyword }: «{ $word }» — не целое число ≥ 0
cs418-sized = { $keyword } нужен размер, а затем числа
cs418-size-word = { $keyword }: размер «{ $size }» — не целое число
cs418-size-zero = { $keyword }: размер не может быть 0
cs418-vertices = { $keyword } { $size }: { $numbers } чисел — не целое число вершин ({ $whole } и { $left } в остатке)
cs418-vertex-index = читается вершина { $index }, а в «position» вершин { $count }
cs418-texture-missing = такого файла рядом с заданием нет
cs418-texture-unreadable = не удаётся прочитать ({ $reason })
cs418-image-size = изображение { $width } × { $height }, а задание рисует { $case_width } × { $case_height }
png-not-an-image = не изображение PNG ({ $reason })
png-too-large = PNG слишком велик
png-broken = повреждённое изображение PNG ({ $reason })
png-colour-type = неожиданный цветовой тип PNG { $kind }
buet-size = «{ $word }» — не размер растра от 1 до { $max }
buet-config-empty = пуст; нужен размер растра «W H»
buet-config-first = первая строка должна быть размером растра «W H»
buet-one-number = ожидалось одно число
buet-z-range = ожидалось «z_front z_rear»
buet-window-negative = left_x и bottom_y должны быть отрицательными (окно — от left_x до −left_x)
buet-z-order = z_front не может превышать z_rear
buet-config-lines = непустых строк { $count }; ожидалась 1 («W H») или 4 («W H», left_x, bottom_y, «z_front z_rear»)
buet-ends = заканчивается там, где ожидалось: { $what }
buet-numbers = ожидалось: { $what } ({ $count } чисел), найдено «{ $found }»
buet-what-eye = положение глаза
buet-what-look = точка, куда смотрят
buet-what-up = направление вверх
buet-what-perspective = fovY aspect near far
buet-what-vertex = вершина треугольника
buet-what-translation = перенос
buet-what-scale = коэффициенты масштаба
buet-what-rotation = угол и ось
buet-pop = pop без парного push
buet-three-coordinates = ожидались три координаты, найдено «{ $found }»
buet-triangles = точек { $count } — не целое число треугольников
cs418-width = ширина
cs418-height = высота

rules-describe = правила { $preset }: { $rows }; { $columns }; { $store }
rules-rows-half-open = строки полуоткрытые (min ≤ y < max), пересечения попарно
rules-rows-closed = строки замкнутые (min ≤ y ≤ max), один отрезок от наименьшего до наибольшего пересечения
rules-rows-top-left = строки «сверху-слева» (min < y ≤ max: центры на верхнем ребре входят, на нижнем нет), пересечения попарно
rules-columns-centre-inside = столбцы, чей центр лежит в отрезке
rules-columns-cell-holds = столбцы от ячейки с x_a до ячейки с x_b
rules-columns-half-open = столбцы, чей центр лежит в [x_l, x_r): центры на левом ребре входят, на правом нет
rules-store-quantized = глубина округляется вверх на половине и насыщается
rules-store-exact = глубина хранится точно

place-vertex-on-scanline = многоугольник { $polygon }: вершина { $vertex } ({ $x }; { $y }) лежит на сканирующей строке ряда { $row }
place-centre-on-edge = пиксел ({ $x }, { $y }): его центр лежит на ребре многоугольника { $polygon }
place-spans = многоугольник { $polygon }: в ряду { $row } отрезков: { $spans }
place-half-depth = пиксел ({ $x }, { $y }), многоугольник { $polygon }: z = { $z } округляется вверх до { $stored }
place-saturation = пиксел ({ $x }, { $y }), многоугольник { $polygon }: z = { $z } округляется до { $rounded }, хранится { $stored }
place-hidden = пиксел ({ $x }, { $y }), многоугольник { $polygon }: z = { $z } не проходит тест против хранимого { $stored }
place-intersecting = многоугольники { $first } и { $second }: каждый где-то перед другим

cs418-elements-range = drawElementsTriangles { $count } { $offset } читает элементы { $offset }…{ $last }, а в «elements» их { $has }
cs418-point-size-range = drawArraysPoints читает размер точки { $index }, а в «pointsize» их { $has }
cs418-texcoord-range = вершина { $index } рисуется с текстурой, а в «texcoord» вершин { $has }
cs418-too-far = вершина попадает в ({ $x }, { $y }) на изображении, слишком далеко от него для растеризации (дальше { $reach } размеров изображения): включите «frustum», чтобы отсечь её
cs418-too-many-primitives = { $count } примитивов не помещаются в 32-битный буфер кадра

file-written = записан { $path }
buet-run-summary = { $path }: { $triangles } { $triangles ->
    [one] треугольник
    [few] треугольника
   *[other] треугольников
} на { $width }×{ $height }, проверено центров пикселов: { $tested }, записано: { $written }
buet-answer-not-a-number = строка { $line }, значение { $value }: «{ $text }» — не число
buet-answer-rows = строк { $rows }; в растре { $height }
buet-none = (нет)
buet-check-matches = { $answer }: каждая строка совпадает с z-буфером { $path }
buet-header-line = строка
buet-header-value = значение
buet-header-answer = ответ
buet-header-right = верно
buet-header-why = почему
buet-cell = ячейка ({ $x }, { $y }): { $why }
buet-extra-value = zsim пишет в этой строке меньше значений: в ответе лишнее
buet-check-differs = { $answer }: { $count ->
    [one] отличается { $count } значение
    [few] отличаются { $count } значения
   *[other] отличаются { $count } значений
} от z-буфера { $path }
cs418-primitive-point = точка из вершин { $vertices } (строка { $line })
cs418-primitive-triangle = треугольник из вершин { $vertices } (строка { $line })
cs418-run-summary = { $path }: { $width } × { $height }, арифметика { $arithmetic }{ $features }: записан { $written }
cs418-compare-same = { $path }: каждый канал каждого пиксела в пределах { $tolerance } (наибольшая разница { $largest })
cs418-compare-differs = { $path }: пикселов, отличающихся больше чем на { $tolerance }: { $count } (наибольшая разница { $largest }):
cs418-compare-pixel = ({ $x }, { $y }): zsim { $ours }, изображение { $theirs }
cs418-compare-more = … и ещё { $count }
cs418-arith-alike = арифметика f64 курса и точная арифметика рисуют все отсчёты одинаково
cs418-arith-disagree = отсчётов, где арифметика f64 курса и точная арифметика расходятся: { $count }
cs418-place-sample = отсчёт ({ $x }, { $y }) пиксела ({ $px }, { $py })
cs418-place-pixel = пиксел ({ $x }, { $y })
cs418-no-span = нет отрезка
cs418-inside = внутри
cs418-outside = снаружи
cs418-why-span = { $primitive }: в ряду { $row } его отрезок { $course } в f64, но { $exact } точно, поэтому x = { $x } { $course_side } в f64 и { $exact_side } точно
cs418-nothing = ничего
cs418-why-depth = обе арифметики покрывают его одними и теми же примитивами, но тест глубины оставляет { $course } в f64 и { $exact } точно (равные глубины или в пределах округления)
file-written-in = записаны { $files } в { $path }
exercise-notes-settings = упражнение: зерно { $seed }, растр { $width }×{ $height }, многоугольников { $polygons }, буфер кадра { $frame_bits } бит, z-буфер { $depth_bits } бит (0 … { $max }), тест глубины { $test }
exercise-notes-asked = заказано: { $asked } (кандидат { $candidate } из последовательности зерна)
exercise-notes-no-case = никакого особого случая
exercise-notes-contains = содержит (найдено в трассе прогона, первое место каждого):
exercise-notes-none = ни одного трудного случая
exercise-notes-next = проверить ответ: zsim check { $path } --frame FRAME.txt --depth DEPTH.txt; оценить группу: zsim grade { $path } CLASS_DIR
png-no-fonts = в этой системе нет шрифтов, и текст пропал бы; запишите SVG (-o FILE.svg)
png-figure-too-large = рисунок слишком велик
error-output = не удаётся записать вывод: { $reason }
memory-header-buffer = буфер
memory-header-cells = ячеек
memory-header-bits-per-cell = бит на ячейку
memory-header-bits = бит
memory-header-bytes = байт
memory-total = всего
memory-at-sample = отсчёте
memory-at-pixel = пикселе
memory-supersampled = , суперсэмплинг { $k }×{ $k } с глубиной в каждом { $at }
memory-heading = { $width }×{ $height } пикселов, буфер кадра { $frame_bits } бит, z-буфер { $depth_bits } бит{ $sampling }
memory-total-line = всего: { $total } байт = { $megabytes }
step-antialias-note = замечание: эта сцена требует суперсэмплинга { $k }×{ $k }; step показывает простое покрытие и глубину каждого центра пиксела до суперсэмплинга и усреднения (`zsim run` показывает усреднённые буферы, `zsim explain --pixel X,Y` — отсчёты каждого пиксела)
step-fixed = в арифметике fixed:{ $bits } вершины сначала привязываются к кратным 1/{ $unit }, затем эти точные правила работают с привязанным многоугольником (`zsim run --arith fixed:{ $bits }` показывает результат)
step-float-exact = точно { $z }
step-float-not-exact = точная арифметика его не покрывает
step-float-edges = реберные функции в центрах столбцов ограничивающего прямоугольника { $first } … { $last }
step-float-no-crossings = пересечений нет
step-float-crossings = пересечения { $crossings }
step-float-heading = в арифметике { $arith }: { $found }
step-float-no-pixel = ни один пиксел не покрыт
step-float-missed = пропущены точные центры x = { $columns }
run-summary = { $path }: многоугольников { $polygons }, проверено центров пикселов: { $tested }, записано: { $written }; эффекты: { $effects }; стадии: { $stages }; чтение { $read } мс, растеризация { $raster } мс, потоков: { $threads } ({ $rate } млн пикселов/с); память: буферы { $buffers }, сцена { $scene }{ $peak }
run-summary-peak = , пик резидентной памяти { $peak }
run-summary-peak-ratio = , пик резидентной памяти { $peak } ({ $ratio }× буферы + сцена)
run-summary-no-effects = нет
run-summary-arith = ; арифметика { $arith }
run-arith-compared = арифметика: { $arith }; в сравнении с точной арифметикой отличаются ячеек буфера кадра: { $frame }, z-буфера: { $depth }
run-frame-after-all = буфер кадра после всех многоугольников:
run-depth-after-all = z-буфер после всех многоугольников:
compare-rules-this = в этой сцене { $rules }
compare-rules-other = для сравнения: { $rules }
compare-rules-same = все пикселы выходят одинаковыми: ни один центр не лежит точно на ребре, где правила расходятся
compare-rules-differ = отличающихся пикселов: { $count }:
compare-rules-nothing = ничем
compare-rules-cell = ({ $x }, { $y }): { $before } → { $after }; покрыт { $covering } по { $rules }, { $other_covering } по { $other_rules }
compare-rules-vertex = центр ({ $x },5, { $y },5) — вершина { $vertex } многоугольника «{ $name }»: решают сходящиеся в ней рёбра, по каждому набору правил как на самих рёбрах
compare-rules-edge = центр ({ $x },5, { $y },5) лежит на ребре ({ $boundary }) многоугольника «{ $name }» от { $from } до { $to }: { $verdict } по { $rules }, { $other_verdict } по { $other_rules }
compare-rules-covered = покрыт
compare-rules-left-out = не покрыт
preset-rogers = правилам учебника
preset-buet = правилам BUET
preset-gl = правилу OpenGL
preset-vulkan = правилу «сверху-слева» Vulkan и Direct3D
variant-identical = совпадает с простым z-буфером (буфер кадра и z-буфер)
variant-differs = отличаются от простого z-буфера ячеек: { $count }
variant-result = результат: { $result }
segments-kind = сегменты: { $count } ({ $segments }), каждый многоугольник отнесён к сегментам, которых касается его ограничивающий прямоугольник
segments-memory = память z-буфера: { $cells } ячеек × { $bits } бит = { $total } бит (весь растр: { $whole_cells } ячеек, { $whole_bits } бит)
segments-visits = посещений многоугольников: { $visits } (весь растр: { $whole })
pixel-order-ray = трассировка луча (правило вершин «слева открыто, справа замкнуто»; граница считается)
pixel-order-arc = метод длины дуги (таблица квадрантов; граница считается)
pixel-order-heading = порядок: для каждого пиксела, для каждого многоугольника, одна переменная глубины (китайский конспект); тест принадлежности: { $test }
pixel-order-header-polygon = многоугольник
pixel-order-header-why = почему тесты принадлежности расходятся
pixel-order-on-boundary = центр лежит точно на границе: дуга считает его внутренним, а правило полуинтервала не включает верхние рёбра и вершины (ребро считается только у нижнего конца)
pixel-order-winding = многоугольник обходит центр { $winding } раз: дуга считает ненулевое число оборотов внутренним, парные пересечения (чёт-нечёт) — внешним
pixel-order-disagree = центров, где дуга и правило сканирующих строк расходятся: { $count }
antialias-at-sample = отсчёте
antialias-at-centre = центре пиксела
antialias-heading = сглаживание: { $k }×{ $k } отсчётов на пиксел, глубина в каждом { $at }; значения — средние по отсчётам (доли от { $samples })
antialias-frame-after = буфер кадра после { $polygon }, усреднённый:
antialias-depth-after = z-буфер после { $polygon }, усреднённый:
transparency-all-match = прозрачность: каждая ячейка совпадает с правильным смешиванием от дальнего к ближнему
transparency-header-drawn = нарисовано
transparency-header-back-to-front = от дальнего к ближнему
transparency-header-polygons = многоугольники там, от дальнего к ближнему
transparency-differs = прозрачность: ячеек, отличающихся от правильного смешивания от дальнего к ближнему: { $count } (локальные ошибки рисования в неправильном порядке: многоугольник за прозрачным, нарисованный после него, не проходит тест глубины):
accuracy-header-mode = режим
accuracy-header-ns = нс на пиксел
accuracy-header-pixels = пикселов
accuracy-header-frame = ячеек кадра ≠ точно
accuracy-header-depth = ячеек глубины ≠ точно
accuracy-header-worst = наибольшая ошибка глубины (уровней)
accuracy-header-time = время к точному
accuracy-header-bits = бит глубины
accuracy-header-fighting = ячеек z-конфликта
accuracy-header-memory = память z-буфера (байт)
accuracy-header-ms = время (мс)
accuracy-set = набор для точности: { $scenes } сцен на { $width }×{ $height } (случайные треугольники в 4, 16, 64 и 256 пикселов с вершинами на сетке 1/256, зерно { $seed }, и 4 трудных случая); время режима — наименьшее из 5 кругов, в каждом из которых режимы работают по очереди
accuracy-sweep = две почти компланарные плоскости, пересекающиеся по x = y (мировые глубины 0 … 1, умноженные на 2^bits уровней; наклон 1/2^20 диапазона на пиксел), { $cells } ячеек:
progress-bands = полос плиток
progress-polygons = многоугольников

# Inputs zsim refuses before reading.
error-not-regular = { $path }: не обычный файл (это { $kind }): zsim читает только обычные файлы
error-too-large = { $path }: больше, чем читает zsim ({ $limit } МиБ)
file-kind-directory = папка
file-kind-fifo = именованный канал (FIFO)
file-kind-device = устройство
file-kind-socket = сокет
file-kind-link = символическая ссылка, по которой zsim не переходит
file-kind-other = не обычный файл
error-not-utf8 = не текст в UTF-8
usage-output-is-input = { $path } — один из входов, которые читает zsim: запишите вывод в другое место
usage-output-would-replace = в { $path } уже есть { $files }{ $more ->
    [0] {""}
   *[other] { " " }и ещё { $more }
}: zsim не заменяет файлы; выберите новую или пустую папку
usage-tile-zero = --tile принимает 1 пиксел и больше (с 0 ничего не рисуется)
stdout-closed = стандартный вывод закрыт
buet-look-at-eye = точка, куда смотрят, совпадает с положением глаза: у взгляда нет направления
buet-up-along-view = направление вверх нулевое или лежит вдоль направления взгляда: у камеры нет ориентации
buet-perspective = fovY и fovY·aspect должны лежать между 0 и 180 градусами, aspect и near быть положительными, а far отличаться от near
buet-rotation-axis = поворот вокруг оси 0 0 0 не имеет направления
token-cut = { $shown }… ({ $count } символов)

# The machine's OpenGL.
gpu-no-library = OpenGL не найден: { $reason } (установите libegl1 libegl-mesa0 libgl1-mesa-dri)
gpu-refused = OpenGL отказал в { $step }: { $reason }
gpu-heading = { $path }, нарисованный { $renderer }, рядом с zsim по правилам сцены и по набору { $preset }
gpu-same = каждый пиксел показывает один и тот же многоугольник на GPU и в zsim
gpu-differ = пикселов с другим многоугольником: { $count }:
gpu-cell = ({ $x }, { $y }): GPU показывает { $gpu }; zsim показывает { $book } по правилам сцены, { $covered } по { $preset }
gpu-background = ничего
gpu-exact-depth = { $polygon } на точной глубине { $depth }
gpu-why-depth = GPU записал глубину { $gpu } (интерполяция в f32, хранение в 24 битах) для { $shown }; по правилам сцены остаётся { $book }
gpu-not-convex = замечание: { $polygon } не выпуклый: GPU рисует его веером треугольников из первой вершины, а это не тот многоугольник
speed-header = { $scene }: треугольников { $triangles } (веера { $polygons } многоугольников{ $skipped ->
    [0] {""}
   *[other] ; ещё { $skipped } ничего не рисуют: вырожденные, видны с ребра, отсечены или вне поля зрения
  }), проверено центров пикселей { $pixels }; zsim на { $threads } { $threads ->
    [one] потоке
   *[other] потоках
}, { $tile ->
    [0] полигон за полигоном
   *[other] плитками по { $tile }
}, против { $renderer } (LP_NUM_THREADS={ $lp }), { $pairs } чередующихся пар после одного неучтённого прогона каждого
speed-result = zsim { $zsim } мс, GPU { $gpu } мс (медианы): zsim тратит { $ratio }× времени GPU (в парах от { $low }× до { $high }×)
speed-fresh = весь прогон zsim в новых буферах, как рисует `zsim run`: { $fresh } мс (медиана), { $ratio }× времени GPU
speed-memory = zsim проверял { $rate } млн центров пикселей в секунду; копия { $megabytes } МБ буферов заняла { $copy } мс ({ $bandwidth } ГБ/с), что при { $bytes } байтах на пиксель, прочитанных и записанных по разу, допускает { $limit } млн пикселей в секунду
usage-compare-gpu-plain = --compare-gpu сравнивает простой алгоритм: эта сцена требует попиксельных эффектов или сглаживания
usage-no-gpu = --compare-gpu: { $reason }
gpu-why-depth-unread = GPU показывает { $shown }; по правилам сцены остаётся { $book } (решили глубины: GPU интерполирует их в f32)
gpu-no-vulkan = устройство Vulkan не найдено: { $reason } (установите mesa-vulkan-drivers)
gpu-not-built = этот zsim собран без возможности { $feature }: соберите его командой `cargo install --path . --features { $feature }`

## What the system and the JSON reader say (words/system.rs)
io-not-found = нет такого файла или папки
io-permission-denied = нет доступа
io-already-exists = он уже существует
io-is-a-directory = это папка
io-not-a-directory = часть пути — не папка
io-storage-full = диск заполнен
io-read-only = файловая система только для чтения
io-not-utf8 = файл — не текст в UTF-8
json-at = { $message } (строка { $line }, позиция { $column })
json-invalid-type = неверный тип: найдено { $found }, а ожидался { $expected }
json-invalid-value = неверное значение: найдено { $found }, а ожидался { $expected }
json-invalid-length = элементов: { $length }, а ожидался { $expected }
json-missing-field = нет поля { $field }
json-unknown-field = неизвестное поле { $field }; возможные поля: { $known }
json-unknown-field-none = неизвестное поле { $field }
json-unknown-variant = неизвестное значение { $variant }; возможные значения: { $known }
json-duplicate-field = поле { $field } задано дважды
json-eof = файл обрывается посреди значения
json-expected-token = ожидался символ { $token }
json-expected-value = ожидалось значение
json-trailing = после конца сцены есть ещё текст
json-trailing-comma = запятая перед закрывающей скобкой
json-key-string = ключ должен быть строкой в кавычках
json-invalid-number = неверное число
json-number-range = число вне допустимого диапазона
json-invalid-escape = неверная escape-последовательность в строке
json-too-deep = слишком глубокая вложенность
json-control = управляющий символ внутри строки
json-found-integer = целое число { $value }
json-found-decimal = десятичное число { $value }
json-found-string = строка { $value }
json-found-bool = { $value }
json-found-null = null
json-found-list = список
json-found-object = объект
json-want-list = список
json-want-string = строка
json-want-bool = true или false
json-want-number = число (или строка с дробью или десятичным числом)
json-want-vertex = вершина [x, y, z] (или [x, y, z, w] в пространстве отсечения)
json-want-object = объект
json-want-whole = целое число
usage-pixel-not-xy = «{ $text }» — не X,Y (например, 20,15)
usage-pixel-coordinate = «{ $text }» — не координата пиксела
usage-arith = «{ $text }» — не режим арифметики: `exact`, `f64`, `f64-incremental`, `f32-incremental`, `f32`, `f32-edge` или `fixed:K` (K от 0 до 24)
usage-missing = не хватает: { $args }
usage-invalid-value = «{ $value }» не подходит для { $arg }: { $reason }
usage-unknown-argument = неизвестный параметр { $arg }
usage-unknown-command = неизвестная команда { $name }
usage-conflict = { $arg } нельзя задавать вместе с { $other }
usage-see-help = справка: zsim --help

## The misconception behind a wrong answer (teach/diagnose.rs)
diagnosis = вероятная причина: { $what } (объясняет { $explained } из { $wrong } { $wrong ->
    [one] неверной ячейки
   *[other] неверных ячеек
})
misconception-truncated = глубины отброшены до целого (округлены вниз), а не округлены до ближайшего целого
misconception-half-down = половины округлены вниз, а не вверх (10,5 записано как 10)
misconception-rounded-compared = с z-буфером сравнивалась округлённая глубина, а не точное z
misconception-no-saturation = глубины за пределами диапазона z-буфера переполнились по кругу, а не насытились
misconception-not-strict = равная глубина пропущена (≥ вместо >)
misconception-reversed = тест глубины перевёрнут (ближе считалось меньшее z)
misconception-last-only = нарисован только последний многоугольник
misconception-one-early = ответ на один многоугольник раньше
misconception-bottom-first = строки записаны начиная с нижней
misconception-corners = пикселы взяты в углах, а не в центрах
misconception-cell-rule = столбцы взяты по клеткам, в которые попадают концы отрезка, а не по центрам внутри отрезка
grade-column-cause = вероятная причина
grade-cause = { $what } ({ $explained } из { $wrong })
grade-causes = вероятные причины в группе:
grade-cause-count = { $what }: { $count } из { $students } { $students ->
    [one] студента
   *[other] студентов
}
answer-more-problems = { "" } · и ещё { $count } { $count ->
    [one] ошибка
    [few] ошибки
   *[many] ошибок
}
usage-no-submission = { $folder }: здесь нет ответа: frame.txt, depth.txt, after-N.frame.txt или after-N.depth.txt
gradescope-test = { $buffer } после { $after }
usage-identity-column = --identity: эта платформа не импортирует по столбцу «{ $column }» (Moodle: email, idnumber, username; Canvas: id, sis-user-id, sis-login-id)
usage-no-points = --points должно быть не меньше 1
figures-not-built = этот zsim собран без рисунков { $format } (возможность figures, выключенная в обычной сборке): соберите его командой `cargo install --path . --features figures`; в пакете Debian они есть. Рисункам SVG и TeX ничего не нужно

## tinyrenderer's OBJ files (courses/tinyrenderer.rs)
obj-vertex-count = у вершины должны быть x, y и z; в этой строке чисел: { $count }
obj-not-a-number = «{ $token }» — не число
obj-face-corners = у грани урока 3 вершины; у этой: { $count }
obj-bad-index = «{ $token }» — не номер вершины (с 1)
obj-too-many-faces = больше { $max } граней
obj-no-vertex = вершины { $index } нет: в файле их { $count }
rules-store-truncated = глубина отбрасывается до целого (округляется вниз) с насыщением
rules-sample-corner = ; выборка в целых точках (x, y), углах пикселов
rules-compare-level = ; сравнивается глубина, округлённая так же, как записывается
rules-min-area = ; многоугольники с ориентированной площадью меньше { $area } пропускаются
stage-store-truncated = запись (отбрасывание дробной части, насыщение до 0…{ $max })
preset-tinyrenderer = урок tinyrenderer про z-буфер
fate-small-area = его ориентированная площадь меньше границы правил (обратная грань или щепка): он пропущен
heading-small-area = { $start }: плоскость { $plane }, пропущен (ориентированная площадь меньше границы правил: обратная грань или щепка)
tinyrenderer-run = { $model }: граней { $faces }, пропущено { $skipped } (площадь меньше 1), нарисовано { $drawn }; записаны zbuffer.tga и framebuffer.tga в { $folder }
tinyrenderer-differ = точная арифметика даёт другой уровень z-буфера, чем f64 урока, в { $count } { $count ->
    [one] пикселе
   *[other] пикселах
}
tinyrenderer-differ-pixel = ({ $x }, { $y }), грань { $face }: f64 { $float }, точно { $exact } (интерполированное z целое; f64 чуть меньше, и отбрасывание дробной части теряет уровень)
tinyrenderer-line = строка { $line }
explain-others = ещё { $count } многоугольников не доходят до сканирующей строки этого пиксела: { $skipped } не рисуются вовсе (пропущены, отсечены или видны с ребра), у { $off } строки лежат в другом месте
explain-corner-sample = по правилам выборка берётся в целой точке ({ $x }, { $y }): zsim рисует сцену, сдвинутую на ½, чтобы этот центр был этой точкой, и координаты ниже — сдвинутые
stored-truncated = в z-буфер записывается { $stored } ({ $value } без дробной части — { $stored })
stored-truncated-saturated = в z-буфер записывается { $stored } ({ $value } без дробной части, с насыщением до { $stored })
usage-tinyrenderer-size = «{ $text }» — не сторона изображения: { $min } … { $max } пикселов
quiz-frame-hint = введите значение, которое будет в буфере кадра, или - если не записывается (q завершает опрос)
quiz-frame-does-not-fit = { $text } не помещается в этот буфер кадра: его ячейки хранят целые значения 0 … { $max }; введите снова
usage-not-a-preset = «{ $text }» — не набор правил: используйте rogers, buet, gl, vulkan (d3d, webgpu) или tinyrenderer
error-outside-folder = { $path }: имя внутри файла должно оставаться в папке этого файла ({ $folder }): без «..» и без абсолютного пути
usage-output-name-too-long = { $path }: имя длиннее, чем допускают файловые системы ({ $max } байт); ничего не записано
usage-output-twice = { $path } была бы записана одной командой дважды; ничего не записано
png-declares-too-many-pixels = PNG объявляет { $width } × { $height } пикселей, больше, чем декодирует zsim ({ $max })
cs418-too-many-samples = fsaa { $level } требует { $samples } отсчётов, больше, чем рисует zsim ({ $max }): уменьшите fsaa или размер изображения
usage-same-answer-twice = { $path }: { $files } отвечают за один и тот же буфер одного состояния: сдайте один
expect-not-states = «{ $text }» — не список состояний: напишите final, each или номера многоугольников от 1 через запятую (1,3)
gradescope-missing = нет файла с этим ответом: сдайте { $file }
gradescope-score-rule = оценка: доля верных ({ $right }) среди { $changed } ячеек, которые сцена меняет, минус такая же доля за каждую из { $stray } ячеек, записанных там, где буфер сохраняет начальное значение; ячейки без ответа не учитываются
gradescope-ambiguous = на это отвечают сразу { $files }: ни один не оценён; сдайте один
gradescope-unused = не оценены (задание их не требует): { $files }
usage-same-student-twice = { $path }: { $files } — оба «{ $student }», когда имена показаны: переименуйте один; ничего не оценено
usage-gradebook-cannot-tell = «{ $first }» и «{ $second }» для журнала оценок — один студент (та же ячейка без учёта регистра): переименуйте один; ничего не записано
png-figure-too-many-pixels = при таком --scale в PNG было бы больше { $max } пикселей: укажите меньше
check-more-cells = … и ещё { $count } { $count ->
    [one] ячейка отличается
    [few] ячейки отличаются
   *[other] ячеек отличаются
}, не перечислены

grade-skipped = не проверен: { $file } — не файл ответа (ИМЯ.frame.txt или ИМЯ.depth.txt)
grade-skipped-near = не проверен: { $file } похож на { $buffer } ученика { $student }: назовите его { $name }

## The browser playground
play-title = Песочница zsim: z-буфер шаг за шагом
play-intro = Меняйте сцену; все буферы ниже рисует библиотека zsim, скомпилированная для вашего браузера.
play-language = Язык
play-scene = Сцена
play-width = ширина
play-height = высота
play-frame-bits = бит буфера кадра
play-depth-bits = бит z-буфера
play-depth-test = тест глубины
play-preset = правила
play-preset-none = как в книге
play-snap = шаг сетки
play-polygon = многоугольник
play-value = значение
play-add-polygon = + многоугольник
play-remove-polygon = − многоугольник
play-add-vertex = + вершина
play-remove-vertex = − вершина
play-json = JSON сцены
play-share = Ссылка на эту сцену
play-shared = Ссылка — в адресной строке: скопируйте её оттуда.
play-buffers = Буферы после каждого многоугольника
play-final = Итоговые буферы (как их печатает zsim run --final)
play-grid = Растр
play-grid-help = Перетащите вершину, чтобы сдвинуть её; щёлкните пиксел, чтобы увидеть его историю.
play-explain = История пиксела
play-stepper = Строка за строкой
play-figure = Рисунок
play-homework = Проверить домашнее задание
play-homework-help = Введите или вставьте матрицу так, как её печатает книга, начиная с верхней строки.
play-check = Проверить
play-answer-grid = Ввести в сетку (начиная с очищенного буфера)
play-after = после
play-your-answer = ваш ответ
play-too-large = Сцена слишком велика, чтобы показать её по ячейкам (больше { $cells } пикселов или { $polygons } многоугольников): показаны только итоговые буферы.
play-not-printed = В этом растре больше { $cells } пикселов: буферы нарисованы, но здесь не печатаются; их печатает zsim run --final.
play-no-antialias = Эта страница рисует сцену без сглаживания; сглаженные изображения показывает zsim run.
play-no-polygon = Такого многоугольника в сцене нет.
play-not-json = Сцена — не JSON: { $reason }
play-bad-edit = Это изменение не подходит к JSON этой сцены.
play-bad-address = В адресе нет сцены: после #scene= должен идти JSON сцены в base64url.

## The lesson (teach::lesson): the same in every front end.
lesson-key-next = следующая строка
lesson-key-back = назад
lesson-key-next-polygon = следующий многоугольник
lesson-key-previous-polygon = предыдущий многоугольник
lesson-key-skip = пропустить вопросы этой строки
lesson-key-quit = выход
lesson-keys = клавиши: { $keys }, g Y перейти к строке Y; ответ проверяется по Enter
lesson-hint-misconception = похоже, что { $what }
lesson-hint-is-written = этот пиксель проходит тест глубины: сравните его точное z с хранимым значением ещё раз
lesson-hint-is-not-written = этот пиксель не проходит тест глубины: сравните его точное z с хранимым значением ещё раз
lesson-hint-centre-on-boundary = центр лежит точно на границе многоугольника: какое правило его решает?
lesson-hint-column-outside = вы взяли столбец, центр которого лежит вне отрезка
lesson-hint-column-left-out = вы пропустили столбец, центр которого лежит внутри отрезка
lesson-hint-other = вычислите z в центре пикселя по плоскости, сравните с хранимым значением, затем округлите
lesson-right = { $said }: верно. { $why }
lesson-right-second = { $said }: верно со второй попытки. { $why }
lesson-try-again = { $said }: пока нет: { $hint } (ещё одна попытка)
lesson-revealed = { $said }: снова неверно. Ответ: { $expected }: { $why }
lesson-skipped = пропущено вопросов: { $count } (считаются неотвеченными)
lesson-score = опрос: с первой попытки { $first }, со второй { $second }, показано { $revealed }, пропущено { $skipped }, всего вопросов { $asked }
lesson-ask-coverage = { $polygon }, строка { $scanline }: центры каких столбцов она покрывает? (столбцы как первый-последний, например 3-7, или - если никаких)
lesson-ask-depth = пиксель ({ $x }, { $y }), хранится { $stored }: что в z-буфере после? (значение, или - если не записан)
lesson-ask-frame = пиксель ({ $x }, { $y }), в буфере кадра { $before }: что в буфере кадра после? (значение, или - если не записан)
lesson-last-try = последняя попытка: { $ask }
lesson-questions-open = на этой строке открытых вопросов: { $open }; сначала ответьте на них или нажмите s, чтобы пропустить
lesson-no-such-polygon = многоугольника { $polygon } нет: в сцене их { $count }
page-no-quiz = Эта страница показывает шаги и ничего не спрашивает: опрос есть в браузерной песочнице (эту страницу команда пишет, когда zsim собран с ней; см. главу руководства «Браузерная песочница») и в zsim step --quiz.
play-scene-name = сцена
page-skip = Пропустить (s)
play-quiz-kind = о чём спрашивает опрос
play-coverage-kind = покрытые столбцы, затем z-буфер
play-examples = Примеры
play-reset = Сбросить
play-copied = Ссылка скопирована.
play-grid-label = Растр: стрелки двигают курсор пикселя, Enter объясняет этот пиксель
play-buffer-kind = какой буфер
play-example-rogers = Пример из книги
play-example-section = Сечение из книги
play-example-less = Тест глубины «меньше»
play-example-cull = Отсечение нелицевых граней
play-example-concave = Невыпуклый многоугольник
play-legend = Значения буфера кадра:
play-hidden = ещё покрытых пикселей: { $count }, спрашиваются по одному
play-legend-value = { $value }
lesson-said-meant = { $said } ({ $meant })
play-error-line = строка { $line }: { $text }
answer-empty = файл пуст: в нём нет ни одной строки ответа
answer-decimal-comma = строка { $line }: в { $text } десятичная запятая; каждая ячейка — целое число (ячейки разделяются пробелами)
usage-answer-without-buffer = { $path } — это ответ: укажите его как --frame { $path } или --depth { $path }
grade-mistakes-more = ещё ячеек, в которых ошиблись двое или больше студентов, не показано: { $count }
check-hint-other-buffer = это в точности { $other }, а не { $buffer }: не сдан ли он как другой буфер?
play-scene-too-long = В этой сцене { $bytes } байт; страница читает сцены до { $max } байт: её нарисует zsim run.
lesson-nothing-to-skip = здесь нет открытых вопросов: пропускать нечего
