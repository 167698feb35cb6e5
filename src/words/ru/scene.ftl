# zsim's words in Russian: reading a scene: its JSON, settings, numbers, geometry; files and what the system says.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

subject-it = он
scene-header = сцена { $path }: { $width }×{ $height } пикселов, буфер кадра { $frame_bits } бит, z-буфер { $depth_bits } бит (0…{ $depth_max }), тест глубины { $test } ({ $rule }), после очистки { $clear }
scene-stages = этапы: { $stages }
scene-effects = эффекты: { $effects }
file-written-about = записан { $path } ({ $about })
file-written-page = записан { $path } (откройте его в браузере; сеть не нужна)
scene-covers-no-pixel = Эта сцена не покрывает ни одного пиксела.
error-read = { $path }: не удаётся прочитать: { $reason }
error-write = { $path }: не удаётся записать: { $reason }
error-polygon = { $path }: { $polygon }: { $problem }
geometry-too-few = вершин { $count }; у многоугольника их должно быть не меньше 3
geometry-too-many = вершин { $count }; zsim принимает не больше { $max }
geometry-out-of-range = у вершины { $vertex } координата { $value } вне точного диапазона: при общем знаменателе многоугольника { $denominator } |координата| × 2 × { $denominator } должна быть не больше 2^4096 (возьмите координаты меньше или меньше знаков после запятой)
digits = { $count } цифр
geometry-off-plane-z = не плоский: вершина { $vertex } отстоит от плоскости { $plane }, проведённой через вершины { $i }, { $j }, { $k }, на Δz = { $off }
geometry-off-plane = не плоский: вершина { $vertex } даёт { $off } вместо 0 в уравнении плоскости { $plane }, проведённой через вершины { $i }, { $j }, { $k }
vertex-decimal-comma = в вершине четыре числа, { $written }, среди вершин [x, y, z]: { $comma } — это десятичная запятая? В JSON дробную часть отделяет точка: напишите { $meant }
clip-space-mixed = смешивает вершины [x, y, z] с вершинами [x, y, z, w] в пространстве отсечения: запишите все вершины многоугольника одинаково
clip-space-alone = задан вершинами [x, y, z, w] в пространстве отсечения, которые переносит на растр преобразование области вывода; они не сочетаются с окном и с эффектом перспективы
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
origin-supersampled = сцена с суперсэмплингом { $factor }×
origin-snapped = сцена, привязанная к fixed:{ $bits }
png-not-an-image = не изображение PNG ({ $reason })
png-too-large = PNG слишком велик
png-broken = повреждённое изображение PNG ({ $reason })
png-colour-type = неожиданный цветовой тип PNG { $kind }
place-vertex-on-scanline = многоугольник { $polygon }: вершина { $vertex } ({ $x }; { $y }) лежит на сканирующей строке ряда { $row }
place-centre-on-edge = пиксел ({ $x }, { $y }): его центр лежит на ребре многоугольника { $polygon }
place-spans = многоугольник { $polygon }: в ряду { $row } отрезков: { $spans }
place-half-depth = пиксел ({ $x }, { $y }), многоугольник { $polygon }: z = { $z } округляется вверх до { $stored }
place-saturation = пиксел ({ $x }, { $y }), многоугольник { $polygon }: z = { $z } округляется до { $rounded }, хранится { $stored }
place-hidden = пиксел ({ $x }, { $y }), многоугольник { $polygon }: z = { $z } не проходит тест против хранимого { $stored }
place-intersecting = многоугольники { $first } и { $second }: каждый где-то перед другим
file-written = записан { $path }
file-written-in = записаны { $files } в { $path }
png-no-fonts = в этой системе нет шрифтов, и текст пропал бы; запишите SVG (-o FILE.svg)
png-figure-too-large = рисунок слишком велик
error-output = не удаётся записать вывод: { $reason }
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
stdout-closed = стандартный вывод закрыт
token-cut = { $shown }… ({ $count } символов)
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
error-outside-folder = { $path }: имя внутри файла должно оставаться в папке этого файла ({ $folder }): без «..» и без абсолютного пути
png-declares-too-many-pixels = PNG объявляет { $width } × { $height } пикселей, больше, чем декодирует zsim ({ $max })
png-figure-too-many-pixels = при таком --scale в PNG было бы больше { $max } пикселей: укажите меньше
limit-cells-or-polygons = Сцена слишком велика, чтобы показать её по ячейкам (больше { $cells } пикселов или { $polygons } многоугольников): показаны только итоговые буферы.
limit-printed-cells = В этом растре больше { $cells } пикселов: буферы нарисованы, но здесь не печатаются; их печатает zsim run --final.
limit-figure-cells = Страница рисует рисунки растров до { $cells } пикселов; этот нарисует zsim figure.
scene-not-json = Сцена — не JSON: { $reason }
edit-does-not-fit = Это изменение не подходит к JSON этой сцены.
address-holds-no-scene = В адресе нет сцены: после #scene= должен идти JSON сцены в base64url.
scene-name-default = сцена
error-at-line = строка { $line }: { $text }
limit-scene-bytes = страница читает сцены до { $max } байт; в этой { $bytes }: её рисует zsim run
limit-page-cells = страница рисует растры до { $max } пикселов; в этом { $cells }: его рисует zsim run
limit-page-polygons = страница рисует до { $max } многоугольников; в этой сцене { $count }: её рисует zsim run
limit-page-vertices = страница рисует многоугольники до { $max } вершин; у многоугольника { $polygon } их { $count }: сцену рисует zsim run
limit-page-reach = страница рисует сцены, многоугольники которых вместе занимают до { $max } пикселов (ограничивающий прямоугольник каждого на растре); в этой { $reach }: её рисует zsim run
limit-recorded-reach = записанная страница проходит сцены, многоугольники которых вместе занимают до { $max } пикселов растра (по ограничивающему прямоугольнику каждого); в этой { $reach }: её проходит zsim step в терминале
limit-recorded-page = записанная страница проходит сцены до { $cells } пикселов и { $polygons } многоугольников; в этой { $has_cells } пикселов и { $has_polygons } { $has_polygons ->
    [one] многоугольник
    [few] многоугольника
   *[many] многоугольников
}: её проходит zsim step в терминале
