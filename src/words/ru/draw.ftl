# zsim's words in Russian: drawing a scene: run's reports, the stages, headings, rules and presets, effects, explain, figures, the GPU and speed.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
depth-test-greater = больше
depth-test-less = меньше
depth-test-greater-equal = больше или равно
depth-test-less-equal = меньше или равно
depth-test-always = всегда
depth-test-never = никогда
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
heading-polygon-scanline = { " " }{ $polygon }, сканирующая строка { $scanline }
heading-end-of-scene = { " конец сцены" }
end-of-scene = конец сцены
span-line = отрезок { $n }: { $left } … { $right }; { $columns }
span-no-centre = ни одного центра
test-passes-uncompared = { $test } пропускает,{ " " }
test-not = { "не " }
outcome-hidden-short = скрыт
depth-steps-from = { ", " }шагов −a/c от { $start }: { $count }
meant-not-written = не записывается
meant-value-written = записанное значение
meant-value-kept = не записывается: значение, которое остаётся
meant-value = значение
frame-after-scanline = буфер кадра после этой строки
depth-after-scanline = z-буфер после этой строки
scanline-of-count = строка { $at } из { $count }
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
fate-outside-view = он вне видимого объёма (−w ≤ x, y, z ≤ w): отсекается целиком и не рисуется
heading-outside-view = { $start }: вне видимого объёма (−w ≤ x, y, z ≤ w): отсекается целиком, не рисуется
heading-view = { "; пространство отсечения: " }внутри видимого объёма { $inside } из { $of } вершин, после отсечения, деления на w и области вывода рисуется как { $n }-угольник
polygon-opacity = непрозрачность { $alpha } вне диапазона 0 … 1
polygon-value-too-wide = значение { $value } не помещается в { $bits }-битный буфер кадра (не больше { $max })
list-or = { $rest } или { $last }
rules-describe = правила { $preset }: { $rows }; { $columns }; { $store }
rules-rows-half-open = строки полуоткрытые (min ≤ y < max), пересечения попарно
rules-rows-closed = строки замкнутые (min ≤ y ≤ max), один отрезок от наименьшего до наибольшего пересечения
rules-rows-top-left = строки «сверху-слева» (min < y ≤ max: центры на верхнем ребре входят, на нижнем нет), пересечения попарно
rules-columns-centre-inside = столбцы, чей центр лежит в отрезке
rules-columns-cell-holds = столбцы от ячейки с x_a до ячейки с x_b
rules-columns-half-open = столбцы, чей центр лежит в [x_l, x_r): центры на левом ребре входят, на правом нет
rules-store-quantized = глубина округляется вверх на половине и насыщается
rules-store-exact = глубина хранится точно
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
run-summary = { $path }: многоугольников { $polygons }, проверено центров пикселов: { $tested }, записано: { $written }; эффекты: { $effects }; стадии: { $stages }; чтение { $read } мс{ $made }, растеризация { $raster } мс, потоков: { $threads } ({ $rate } млн пикселов/с); память: буферы { $buffers }, сцена { $scene }{ $peak }
run-summary-peak = , пик резидентной памяти { $peak }
run-summary-peak-ratio = , пик резидентной памяти { $peak } ({ $ratio }× буферы + сцена)
run-summary-made = , создание буферов { $made } мс
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
speed-fresh = весь прогон zsim с созданием новых буферов (как создание буферов и растеризация `zsim run` вместе): { $fresh } мс (медиана), { $ratio }× времени GPU
speed-memory = zsim проверял { $rate } млн центров пикселей в секунду; копия { $megabytes } МБ буферов заняла { $copy } мс ({ $bandwidth } ГБ/с), что при { $bytes } байтах на пиксель, прочитанных и записанных по разу, допускает { $limit } млн пикселей в секунду
gpu-why-depth-unread = GPU показывает { $shown }; по правилам сцены остаётся { $book } (решили глубины: GPU интерполирует их в f32)
gpu-no-vulkan = устройство Vulkan не найдено: { $reason } (установите mesa-vulkan-drivers)
gpu-not-built = этот zsim собран без возможности { $feature }: соберите его командой `cargo install --path . --features { $feature }`
figures-not-built = этот zsim собран без рисунков { $format } (возможность figures, выключенная в обычной сборке): соберите его командой `cargo install --path . --features figures`; в пакете Debian они есть. Рисункам SVG и TeX ничего не нужно
rules-store-truncated = глубина отбрасывается до целого (округляется вниз) с насыщением
rules-sample-corner = ; выборка в целых точках (x, y), углах пикселов
rules-compare-level = ; сравнивается глубина, округлённая так же, как записывается
rules-min-area = ; многоугольники с ориентированной площадью меньше { $area } пропускаются
stage-store-truncated = запись (отбрасывание дробной части, насыщение до 0…{ $max })
preset-tinyrenderer = урок tinyrenderer про z-буфер
fate-small-area = его ориентированная площадь меньше границы правил (обратная грань или щепка): он пропущен
heading-small-area = { $start }: плоскость { $plane }, пропущен (ориентированная площадь меньше границы правил: обратная грань или щепка)
explain-others = ещё { $count } многоугольников не доходят до сканирующей строки этого пиксела: { $skipped } не рисуются вовсе (пропущены, отсечены или видны с ребра), у { $off } строки лежат в другом месте
explain-corner-sample = по правилам выборка берётся в целой точке ({ $x }, { $y }): zsim рисует сцену, сдвинутую на ½, чтобы этот центр был этой точкой, и координаты ниже — сдвинутые
stored-truncated = в z-буфер записывается { $stored } ({ $value } без дробной части — { $stored })
stored-truncated-saturated = в z-буфер записывается { $stored } ({ $value } без дробной части, с насыщением до { $stored })
heading-scene = Сцена
heading-scene-json = JSON сцены
heading-buffers-each-polygon = Буферы после каждого многоугольника
heading-final-buffers = Итоговые буферы (как их печатает zsim run --final)
heading-raster = Растр
heading-pixel-history = История пиксела
heading-scanline-by-scanline = Строка за строкой
heading-figure = Рисунок
heading-homework = Проверить домашнее задание
antialias-not-drawn = Эта страница рисует сцену без сглаживания; сглаженные изображения показывает zsim run.
heading-examples = Примеры
buffer-kind-label = какой буфер
pixels-hidden-asked = ещё покрытых пикселей: { $count }, спрашиваются по одному
