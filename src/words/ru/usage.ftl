# zsim's words in Russian: requests that do not fit the command or the scene.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

usage-arith-plain-rules = арифметика { $arith } моделирует простой алгоритм по правилам учебника; эта сцена требует других правил или попиксельных эффектов, которые рисует точная арифметика
usage-arith-greater-or-less = арифметика { $arith } моделирует тесты глубины greater и less; эта сцена требует { $test }, который рисует точная арифметика
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
usage-not-a-hard-case = «{ $name }» — не трудный случай: { $names }
usage-exercise-size = упражнение имеет от 4 до 64 пикселов по стороне, а не { $width }×{ $height }
usage-exercise-polygons = в упражнении от 1 до 8 многоугольников, а не { $count }
usage-exercise-bits = в упражнении вручную буфер кадра имеет от 1 до 8 битов, а z-буфер от 1 до 16
usage-exercise-two-polygons = для hidden и intersecting нужны два многоугольника или больше
usage-exercise-not-found = за { $tries } попыток не нашлось сцены из { $polygons } многоугольников на растре { $width }×{ $height } со всеми случаями { $cases }; попросите меньше случаев, больше многоугольников или больший растр
usage-inside-needs-pixel-order = --inside выбирает тест «точка в многоугольнике» для --order pixels; добавьте --order pixels
usage-tiles-need-format-none = --tile и --threads относятся к --format none, --final и --after (иначе показывается состояние после каждого многоугольника, нарисованного по порядку)
usage-format-none-is-plain = --format none подводит итог цикла z-буфера; с --segments, --order pixels или сглаживанием используйте text или json
usage-no-scanlines = { $polygon } не имеет сканирующих строк: { $why }
usage-scanline-rows = { $reach }: его строки { $first } … { $last }
usage-scanline-no-rows = { $reach }: он не достигает ни одной строки растра
usage-output-is-input = { $path } — один из входов, которые читает zsim: запишите вывод в другое место
usage-output-would-replace = в { $path } уже есть { $files }{ $more ->
    [0] {""}
   *[other] { " " }и ещё { $more }
}: zsim не заменяет файлы; выберите новую или пустую папку
usage-tile-zero = --tile принимает 1 пиксел и больше (с 0 ничего не рисуется)
usage-compare-gpu-plain = с GPU сравнивается простой алгоритм: эта сцена требует попиксельных эффектов или сглаживания
usage-pixel-not-xy = «{ $text }» — не X,Y (например, 20,15)
usage-pixel-coordinate = «{ $text }» — не координата пиксела
usage-arith = «{ $text }» — не режим арифметики: `exact`, `f64`, `f64-incremental`, `f32-incremental`, `f32`, `f32-edge` или `fixed:K` (K от 0 до 24)
usage-missing = не хватает: { $args }
usage-invalid-value = «{ $value }» не подходит для { $arg }: { $reason }
usage-unknown-argument = неизвестный параметр { $arg }
usage-unknown-command = неизвестная команда { $name }
usage-conflict = { $arg } нельзя задавать вместе с { $other }
usage-see-help = справка: zsim --help
usage-no-submission = { $folder }: здесь нет ответа: frame.txt, depth.txt, after-N.frame.txt или after-N.depth.txt
usage-identity-column = --identity: эта платформа не импортирует по столбцу «{ $column }» (Moodle: email, idnumber, username; Canvas: id, sis-user-id, sis-login-id)
usage-no-points = --points должно быть не меньше 1
usage-tinyrenderer-size = «{ $text }» — не сторона изображения: { $min } … { $max } пикселов
usage-not-a-preset = «{ $text }» — не набор правил: используйте rogers, buet, gl, vulkan (d3d, webgpu) или tinyrenderer
segments-form = «{ $text }» — не strips:N, tiles:N и не rows:1 (N ≥ 1)
segments-count = «{ $count }» — не целое число
segments-rows = rows принимает только 1 (по одной строке развёртки)
usage-output-name-too-long = { $path }: имя длиннее, чем допускают файловые системы ({ $max } байт); ничего не записано
usage-output-twice = { $path } была бы записана одной командой дважды; ничего не записано
usage-same-answer-twice = { $path }: { $files } отвечают за один и тот же буфер одного состояния: сдайте один
grade-left-out-of-import = не вошли в журнал оценок: «{ $first }» и «{ $second }» для журнала — один студент (та же ячейка без учёта регистра): переименуйте один и импортируйте их строки снова
usage-answer-without-buffer = { $path } — это ответ: укажите его как --frame { $path } или --depth { $path }
usage-line-too-long = строка длиннее { $max } байт: урок заканчивается здесь, его итог выше
usage-html-quiz = --html --quiz записывает песочницу, викторина которой считает точно: уберите --arith
usage-no-playground = этот zsim собран без браузерной песочницы: установите пакет Debian или архив выпуска, в которых она есть, или соберите zsim с ней (web/build, затем ZSIM_PLAYGROUND=target/web cargo build)
