# zsim's words in Russian: the courses' files and commands: CS 418, BUET, tinyrenderer.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
cs418-textures-too-large = вместе с этой текстуры задания заняли бы { $pixels } пикселей; текстуры одного задания вместе занимают не больше { $max }
cs418-texture-unreadable = не удаётся прочитать ({ $reason })
cs418-image-size = изображение { $width } × { $height }, а задание рисует { $case_width } × { $case_height }
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
cs418-elements-range = drawElementsTriangles { $count } { $offset } читает элементы { $offset }…{ $last }, а в «elements» их { $has }
cs418-point-size-range = drawArraysPoints читает размер точки { $index }, а в «pointsize» их { $has }
cs418-colour-range = читается вершина { $index }, а в «color» вершин { $has }
cs418-texcoord-range = вершина { $index } рисуется с текстурой, а в «texcoord» вершин { $has }
cs418-too-far = вершина попадает в ({ $x }, { $y }) на изображении, слишком далеко от него для растеризации (дальше { $reach } размеров изображения): включите «frustum», чтобы отсечь её
cs418-too-many-primitives = { $count } примитивов не помещаются в 32-битный буфер кадра
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
buet-look-at-eye = точка, куда смотрят, совпадает с положением глаза: у взгляда нет направления
buet-up-along-view = направление вверх нулевое или лежит вдоль направления взгляда: у камеры нет ориентации
buet-perspective = fovY и fovY·aspect должны лежать между 0 и 180 градусами, aspect и near быть положительными, а far отличаться от near
buet-rotation-axis = поворот вокруг оси 0 0 0 не имеет направления
obj-vertex-count = у вершины должны быть x, y и z; в этой строке чисел: { $count }
obj-not-a-number = «{ $token }» — не число
obj-face-corners = у грани урока 3 вершины; у этой: { $count }
obj-bad-index = «{ $token }» — не номер вершины (с 1)
obj-too-many-faces = больше { $max } граней
obj-no-vertex = вершины { $index } нет: в файле их { $count }
tinyrenderer-run = { $model }: граней { $faces }, пропущено { $skipped } (площадь меньше 1), нарисовано { $drawn }; записаны zbuffer.tga и framebuffer.tga в { $folder }
tinyrenderer-differ = точная арифметика даёт другой уровень z-буфера, чем f64 урока, в { $count } { $count ->
    [one] пикселе
   *[other] пикселах
}
tinyrenderer-differ-pixel = ({ $x }, { $y }), грань { $face }: f64 { $float }, точно { $exact } (интерполированное z целое; f64 чуть меньше, и отбрасывание дробной части теряет уровень)
file-line = строка { $line }
cs418-too-many-samples = fsaa { $level } требует { $samples } отсчётов, больше, чем рисует zsim ({ $max }): уменьшите fsaa или размер изображения
