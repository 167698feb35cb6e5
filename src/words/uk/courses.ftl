# zsim's words in Ukrainian: the courses' files and commands: CS 418, BUET, tinyrenderer.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

cs418-second-png = другий рядок «png» (файл називає одне зображення, у першому рядку)
cs418-before-png = «{ $keyword }» стоїть до рядка «png WIDTH HEIGHT FILE», який має бути першим
cs418-flag-numbers = «{ $keyword }» не приймає чисел, знайдено { $found }
cs418-fsaa = fsaa { $level }: рівень має бути від 1 до 8
cs418-size = { $keyword } { $size }: розмір має бути { $allowed }
cs418-not-an-index = elements: «{ $word }» — не індекс (ціле число ≥ 0)
cs418-matrix = uniformMatrix потрібні 16 чисел, знайдено { $found }
cs418-count = { $keyword }: кількість { $count } не кратна 3
cs418-texture-name = texture потрібна назва файлу
cs418-texture = текстура «{ $name }»: { $why }
cs418-no-png = немає рядка «png WIDTH HEIGHT FILE»: чи це файл CS 418?
cs418-png-words = png потрібні WIDTH HEIGHT FILE, знайдено слів: { $found }
cs418-png-side = png: { $what } «{ $word }» має бути цілим числом від 1 до { $max }
cs418-png-file = png: «{ $file }» має бути простою назвою файлу, без тек
cs418-not-a-number = { $keyword }: «{ $word }» — не число
cs418-integers = { $keyword } потрібно цілих чисел: { $count }, знайдено { $found }
cs418-not-a-whole-number = { $keyword }: «{ $word }» — не ціле число ≥ 0
cs418-sized = { $keyword } потрібен розмір, а потім числа
cs418-size-word = { $keyword }: розмір «{ $size }» — не ціле число
cs418-size-zero = { $keyword }: розмір не може бути 0
cs418-vertices = { $keyword } { $size }: { $numbers } чисел — не ціла кількість вершин ({ $whole } і { $left } в остачі)
cs418-vertex-index = читається вершина { $index }, а в «position» вершин { $count }
cs418-texture-missing = такого файлу поруч із завданням немає
cs418-textures-too-large = разом із цією текстури завдання зайняли б { $pixels } пікселів; текстури одного завдання разом займають не більше { $max }
cs418-texture-unreadable = не вдається прочитати ({ $reason })
cs418-image-size = зображення { $width } × { $height }, а завдання малює { $case_width } × { $case_height }
buet-size = «{ $word }» — не розмір растра від 1 до { $max }
buet-config-empty = порожній; потрібен розмір растра «W H»
buet-config-first = перший рядок має бути розміром растра «W H»
buet-one-number = очікувалося одне число
buet-z-range = очікувалося «z_front z_rear»
buet-window-negative = left_x і bottom_y мають бути від'ємними (вікно — від left_x до −left_x)
buet-z-order = z_front не може перевищувати z_rear
buet-config-lines = непорожніх рядків { $count }; очікувався 1 («W H») або 4 («W H», left_x, bottom_y, «z_front z_rear»)
buet-ends = закінчується там, де очікувалося: { $what }
buet-numbers = очікувалося: { $what } ({ $count } чисел), знайдено «{ $found }»
buet-what-eye = положення ока
buet-what-look = точка, куди дивляться
buet-what-up = напрямок угору
buet-what-perspective = fovY aspect near far
buet-what-vertex = вершина трикутника
buet-what-translation = перенесення
buet-what-scale = коефіцієнти масштабу
buet-what-rotation = кут і вісь
buet-pop = pop без парного push
buet-three-coordinates = очікувалися три координати, знайдено «{ $found }»
buet-triangles = точок { $count } — не ціла кількість трикутників
cs418-width = ширина
cs418-height = висота
cs418-elements-range = drawElementsTriangles { $count } { $offset } читає елементи { $offset }…{ $last }, а в «elements» їх { $has }
cs418-point-size-range = drawArraysPoints читає розмір точки { $index }, а в «pointsize» їх { $has }
cs418-colour-range = читається вершина { $index }, а в «color» вершин { $has }
cs418-texcoord-range = вершина { $index } малюється з текстурою, а в «texcoord» вершин { $has }
cs418-too-far = вершина потрапляє в ({ $x }, { $y }) на зображенні, надто далеко від нього для растеризації (далі { $reach } розмірів зображення): увімкніть «frustum», щоб відсікти її
cs418-too-many-primitives = { $count } примітивів не вміщуються в 32-бітний буфер кадру
buet-run-summary = { $path }: { $triangles } { $triangles ->
    [one] трикутник
    [few] трикутники
   *[other] трикутників
} на { $width }×{ $height }, перевірено центрів пікселів: { $tested }, записано: { $written }
buet-answer-not-a-number = рядок { $line }, значення { $value }: «{ $text }» — не число
buet-answer-rows = рядків { $rows }; у растрі { $height }
buet-none = (немає)
buet-check-matches = { $answer }: кожен рядок збігається із z-буфером { $path }
buet-header-line = рядок
buet-header-value = значення
buet-header-answer = відповідь
buet-header-right = правильно
buet-header-why = чому
buet-cell = комірка ({ $x }, { $y }): { $why }
buet-extra-value = zsim пише в цьому рядку менше значень: у відповіді зайве
buet-check-differs = { $answer }: { $count ->
    [one] відрізняється { $count } значення
    [few] відрізняються { $count } значення
   *[other] відрізняються { $count } значень
} від z-буфера { $path }
cs418-primitive-point = точка з вершин { $vertices } (рядок { $line })
cs418-primitive-triangle = трикутник з вершин { $vertices } (рядок { $line })
cs418-run-summary = { $path }: { $width } × { $height }, арифметика { $arithmetic }{ $features }: записано { $written }
cs418-compare-same = { $path }: кожен канал кожного пікселя в межах { $tolerance } (найбільша різниця { $largest })
cs418-compare-differs = { $path }: пікселів, що відрізняються більш ніж на { $tolerance }: { $count } (найбільша різниця { $largest }):
cs418-compare-pixel = ({ $x }, { $y }): zsim { $ours }, зображення { $theirs }
cs418-compare-more = … і ще { $count }
cs418-arith-alike = арифметика f64 курсу й точна арифметика малюють усі відліки однаково
cs418-arith-disagree = відліків, де арифметика f64 курсу й точна арифметика розходяться: { $count }
cs418-place-sample = відлік ({ $x }, { $y }) пікселя ({ $px }, { $py })
cs418-place-pixel = піксель ({ $x }, { $y })
cs418-no-span = немає відрізка
cs418-inside = всередині
cs418-outside = зовні
cs418-why-span = { $primitive }: у ряду { $row } його відрізок { $course } у f64, але { $exact } точно, тож x = { $x } { $course_side } у f64 і { $exact_side } точно
cs418-nothing = нічого
cs418-why-depth = обидві арифметики покривають його тими самими примітивами, але тест глибини залишає { $course } у f64 і { $exact } точно (рівні глибини або в межах округлення)
buet-look-at-eye = точка, куди дивляться, збігається з положенням ока: погляд не має напрямку
buet-up-along-view = напрямок угору нульовий або лежить уздовж напрямку погляду: камера не має орієнтації
buet-perspective = fovY і fovY·aspect мають лежати між 0 і 180 градусами, aspect і near бути додатними, а far відрізнятися від near
buet-rotation-axis = поворот навколо осі 0 0 0 не має напрямку
obj-vertex-count = у вершини мають бути x, y і z; у цьому рядку чисел: { $count }
obj-not-a-number = «{ $token }» — не число
obj-face-corners = у грані уроку 3 вершини; у цієї: { $count }
obj-bad-index = «{ $token }» — не номер вершини (з 1)
obj-too-many-faces = понад { $max } граней
obj-no-vertex = вершини { $index } немає: у файлі їх { $count }
tinyrenderer-run = { $model }: граней { $faces }, пропущено { $skipped } (площа менша за 1), намальовано { $drawn }; записано zbuffer.tga і framebuffer.tga в { $folder }
tinyrenderer-differ = точна арифметика дає інший рівень z-буфера, ніж f64 уроку, у { $count } { $count ->
    [one] пікселі
   *[other] пікселях
}
tinyrenderer-differ-pixel = ({ $x }, { $y }), грань { $face }: f64 { $float }, точно { $exact } (інтерпольоване z ціле; f64 трохи менше, і відкидання дробової частини втрачає рівень)
file-line = рядок { $line }
cs418-too-many-samples = fsaa { $level } потребує { $samples } відліків, більше, ніж малює zsim ({ $max }): зменште fsaa або розмір зображення
