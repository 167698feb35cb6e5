# zsim's words in Russian: stepping and the lesson: the stepper's views and keys, the questions, hints and misconceptions, the page's controls.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
title-stepper = zsim step ·{ $heading } · { $view }{ $score } · ? клавиши
score-short = { " · опрос " }{ $right }/{ $asked }
key-does-nothing = эта клавиша здесь ничего не делает: ? покажет клавиши
no-later-polygon = ни один следующий многоугольник не покрывает пикселов
no-earlier-polygon = ни один предыдущий многоугольник не покрывает пикселов
go-to-row-prompt = перейти к сканирующей строке ряда: { $text }▏ (Enter — перейти, Esc — отмена)
keys-summary = n/→ дальше · b/← назад · p/P многоугольник · g перейти · f/z буфер · m по пикселам · q выход
no-scanline = нет сканирующей строки
columns-shown = x { $first } … { $last } из 0 … { $max }
pixel-table-heading = x { $z } тест → в z-буфер (кадр)
keys-pixel-by-pixel = m: по пикселам, с объяснениями
pixel-centre-depth = ({ $x }, { $y }): центр x = { $centre }, z = { $z }{ $steps }
keys-heading = { " клавиши " }
keys-help =
    g                  перейти к сканирующей строке ряда
    f / z              показать буфер кадра / z-буфер
    m                  по пикселам / по строкам
    PgUp PgDn < >      прокрутить растр
    { "[ ]" }                прокрутить таблицу
    ?                  эти клавиши (любая клавиша закрывает)

    жёлтым: покрытые пикселы отрезка
    голубым: прежние записи этого многоугольника
quiz-mistakes = ваши ошибки:
quiz-coverage-hint = введите покрытые столбцы как первый-последний (несколько отрезков через пробел: 3-5 9-12) или -, если ни одного
quiz-coverage-why = отрезки: { $spans }; столбец покрыт, если его центр x + 1/2 лежит в одном из них
quiz-coverage-mistake = строка { $row } { $polygon }: ваш ответ — столбцы { $said }, верно { $right }: { $why }
quiz-depth-hint = введите значение, которое будет в z-буфере, или - если не записывается (q завершает опрос)
quiz-not-an-answer = «{ $text }» — не ответ: { $hint }
quiz-does-not-fit = { $text } не помещается в этот z-буфер: его ячейки хранят целые уровни 0 … { $max }; введите снова
quiz-keeps = - (остаётся { $value })
quiz-depth-mistake = ({ $x }, { $y }) { $polygon }: ваш ответ { $said }, верно { $right }: { $reason }
command-back = ◀ Назад (b)
command-next = Дальше ▶ (n)
command-previous-polygon = ◀◀ Многоугольник (P)
command-next-polygon = Многоугольник ▶▶ (p)
command-show-frame = Буфер кадра (f)
command-show-depth = Z-буфер (z)
quiz-label = опрос
column-stored = было
column-depth-after = z-буфер после
column-why = почему
keeps-value = – (остаётся { $value })
command-check-answers = Проверить ответы
step-skip-fate = { $polygon }: { $why }
step-skip-no-scanline = { $polygon }: не достигает ни одной сканирующей строки растра
step-skip-no-centre = { $polygon }, сканирующая строка { $scanline }: не покрыт ни один центр пиксела
step-skip-no-centre-no-crossings = { $polygon }, сканирующая строка { $scanline }: не покрыт ни один центр пиксела (пересечений нет)
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
pixel-order-ray = трассировка луча (правило вершин «слева открыто, справа замкнуто»; граница считается)
pixel-order-arc = метод длины дуги (таблица квадрантов; граница считается)
pixel-order-heading = порядок: для каждого пиксела, для каждого многоугольника, одна переменная глубины (китайский конспект); тест принадлежности: { $test }
pixel-order-header-polygon = многоугольник
pixel-order-header-why = почему тесты принадлежности расходятся
pixel-order-on-boundary = центр лежит точно на границе: дуга считает его внутренним, а правило полуинтервала не включает верхние рёбра и вершины (ребро считается только у нижнего конца)
pixel-order-winding = многоугольник обходит центр { $winding } раз: дуга считает ненулевое число оборотов внутренним, парные пересечения (чёт-нечёт) — внешним
pixel-order-disagree = центров, где дуга и правило сканирующих строк расходятся: { $count }
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
quiz-frame-hint = введите значение, которое будет в буфере кадра, или - если не записывается (q завершает опрос)
quiz-frame-does-not-fit = { $text } не помещается в этот буфер кадра: его ячейки хранят целые значения 0 … { $max }; введите снова
title-scene-editor = Песочница zsim: z-буфер шаг за шагом
intro-scene-editor = Меняйте сцену; все буферы ниже рисует библиотека zsim, скомпилированная для вашего браузера.
field-language = Язык
field-width = ширина
field-height = высота
field-frame-bits = бит буфера кадра
field-depth-bits = бит z-буфера
field-depth-test = тест глубины
field-preset = правила
field-preset-none = как в книге
field-snap = шаг сетки
field-polygon = многоугольник
field-value = значение
command-add-polygon = + многоугольник
command-remove-polygon = − многоугольник
command-add-vertex = + вершина
command-remove-vertex = − вершина
command-copy-link = Ссылка на эту сцену
link-in-address-bar = Ссылка — в адресной строке: скопируйте её оттуда.
raster-help = Перетащите вершину, чтобы сдвинуть её; щёлкните пиксел, чтобы увидеть его историю.
homework-help = Введите или вставьте матрицу так, как её печатает книга, начиная с верхней строки.
command-check = Проверить
column-after = после
column-your-answer = ваш ответ
no-such-polygon = Такого многоугольника в сцене нет.
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
lesson-right = { $said }: верно. { $why }
lesson-right-second = { $said }: верно со второй попытки. { $why }
lesson-try-again = { $said }: пока нет: { $hint } (ещё одна попытка)
lesson-hint-neighbouring-row = это столбцы соседней строки, ниже или выше: эта строка развёртки — y = строка + ½
lesson-hint-rounded-up = похоже, вы округлили вверх: z-буфер хранит ближайшее целое (половины вверх)
lesson-hint-half-down = похоже, вы округлили половину вниз: половины округляются вверх
lesson-try-again-plain = { $said }: пока нет (ещё одна попытка)
lesson-revealed = { $said }: снова неверно. Ответ: { $expected }: { $why }
lesson-skipped = пропущено вопросов: { $count } (считаются неотвеченными)
lesson-score = опрос: с первой попытки { $first }, со второй { $second }, показано { $revealed }, пропущено { $skipped }, всего вопросов { $asked }
lesson-ask-coverage = { $polygon }, строка { $scanline }: центры каких столбцов она покрывает? (столбцы как первый-последний, например 3-7, или - если никаких)
lesson-ask-depth = пиксель ({ $x }, { $y }), хранится { $stored }: что в z-буфере после? (значение, или - если не записан)
lesson-ask-frame = пиксель ({ $x }, { $y }), в буфере кадра { $before }: что в буфере кадра после? (значение, или - если не записан)
lesson-last-try = последняя попытка: { $ask }
lesson-questions-open = на этой строке открытых вопросов: { $open }; сначала ответьте на них или нажмите s, чтобы пропустить
lesson-no-such-polygon = многоугольника { $polygon } нет: в сцене их { $count }
quiz-not-on-recorded-steps = Эта страница показывает шаги и ничего не спрашивает: опрос есть в браузерной песочнице (эту страницу команда пишет, когда zsim собран с ней; см. главу руководства «Браузерная песочница») и в zsim step --quiz.
command-skip = Пропустить (s)
command-end-quiz = Закончить тест (q)
quiz-kind-label = о чём спрашивает опрос
quiz-kind-coverage = покрытые столбцы, затем z-буфер
command-reset = Сбросить
link-copied = Ссылка скопирована.
raster-label = Растр: стрелки двигают курсор пикселя, Enter объясняет этот пиксель
example-rogers = Пример из книги
example-section = Сечение из книги
example-less = Тест глубины «меньше»
example-cull = Отсечение нелицевых граней
example-concave = Невыпуклый многоугольник
legend-heading = Значения буфера кадра:
legend-value = { $value }
lesson-said-meant = { $said } ({ $meant })
lesson-nothing-to-skip = здесь нет открытых вопросов: пропускать нечего
step-line-not-text = эта строка — не текст (UTF-8): введите её снова
lesson-hidden-until-answered = скрыто, пока на вопросы этой строки не ответят или их не пропустят
