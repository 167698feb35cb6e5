# Слова zsim українською, у термінах статті «Z-буферизація»: піксель,
# буфер кадру, z-буфер, багатокутник, рядок сканування.

buffer-frame = буфер кадру
buffer-depth = z-буфер
polygon-name = { $named ->
    [yes] багатокутник { $number } «{ $name }»
   *[no] багатокутник { $number }
}
polygon-after = { $named ->
    [yes] багатокутника { $number } «{ $name }»
   *[no] багатокутника { $number }
}
span = { $left } … { $right }
scanline = y = { $y }
list-and = { " і " }
list-semicolon = { "; " }
# Decimals take the comma, so lists of numbers take semicolons.
list-comma = { "; " }

winding-cw = за годинниковою стрілкою
winding-ccw = проти годинникової стрілки

stored-whole = в z-буфер записується { $stored }
stored-rounded-up = в z-буфер записується { $stored } ({ $value } округлюється вгору до { $stored })
stored-rounded = в z-буфер записується { $stored } ({ $value } округлюється до { $stored })
stored-saturated = в z-буфер записується { $stored } ({ $value } округлюється до { $rounded } й обмежується значенням { $stored })
stored-exact = в z-буфер записується { $stored } (точно)

z-w-buffer = { $w } (глибина в системі координат спостерігача для w-буфера; після проєціювання z' = { $z })
z-projected = { $z } (z' після проєціювання; глибина в системі координат спостерігача w = { $w })
z-beyond = (поза межами 128-бітної точної арифметики)

test-passed = { $z } { $op } { $stored }
test-failed = { $z }, умова z { $op } { $stored } не виконується
test-uncompared = { $z } (тест глибини { $test }; у z-буфері було { $stored })
rule-compared = z { $op } значення в z-буфері
rule-always = проходить будь-який фрагмент
rule-never = не проходить жоден фрагмент

frame-blended = { $frame } (непрозорість { $alpha }: { $alpha }·{ $value } + { $rest }·{ $under } під ним, половина округлюється вгору)
reason-written = z = { $test }, тому { $stored }, а в буфер кадру — { $frame }
reason-hidden = z = { $test }: піксель прихований, нічого не змінюється
reason-outside-range = z = { $z } поза діапазоном глибини { $front } … { $rear }: фрагмент відкидається
reason-beyond-section = z = { $test }, але переріз залишає лише z { $op } { $section }: не записується

fate-culled = відкидається як нелицьовий: його вершини обходяться { $winding }, тому він не малюється
fate-edge-on = видно з ребра (c = 0): не покриває жодного пікселя
fate-degenerate = вироджений (нормаль за Ньюелом нульова): не покриває жодного пікселя
fate-clipped = усі вершини лежать за ближньою площиною: відсікається повністю й не малюється

entry-no-row = його діапазон за y не сягає рядка сканування { $scanline }{ $tie }
entry-covered = на рядку сканування { $scanline } він займає відрізок { $span }, у якому лежить центр x = { $centre }{ $tie }; { $reason }
entry-covered-no-span = на рядку сканування { $scanline } він покриває центр x = { $centre }{ $tie }; { $reason }
entry-not-inside = на рядку сканування { $scanline } { $spans }; центр x = { $centre } не потрапляє всередину{ $tie }
spans-none = { $subject } не перетинає рядка
spans-some = { $subject } займає { $spans }
subject-it = він
tie-wrap = { " (" }{ $text })

why-covers = { $polygon } покриває ({ $x }, { $y }): z = { $test }, тому { $result }
why-later = { "; потім " }{ $list }
why-later-item = { $polygon } ({ $reason })
result-frame = у буфері кадру { $value }
cleared-frame = тло { $value }
cleared-depth = початкова глибина { $value }
why-covered-item = { $polygon } покриває його, але { $reason }
why-nothing-written = у ({ $x }, { $y }) нічого не записано: { $list }; там залишається { $cleared }
why-none-reaches = жоден багатокутник не покриває ({ $x }, { $y }): жоден не сягає рядка сканування { $scanline }; там залишається { $cleared }
why-not-covered = жоден багатокутник не покриває ({ $x }, { $y }): на рядку сканування { $scanline } { $list }; там залишається { $cleared }

boundary-top = верхньому ребрі
boundary-bottom = нижньому ребрі
boundary-left = лівому ребрі
boundary-right = правому ребрі
boundary-vertex = вершині
tie-vertex = центр збігається з вершиною { $point }: вирішують ребра, що в ній сходяться, за правилом: { $rule }
tie-edge-in = центр лежить точно на { $boundary } від { $a } до { $b }, і { $rule } його включає
tie-edge-out = центр лежить точно на { $boundary } від { $a } до { $b }, і { $rule } його виключає
rule-columns-centre = правило книги для стовпців (центри в [x_l, x_r], кінці включно)
rule-columns-cell = правило BUET для стовпців (від клітинки з x_a до клітинки з x_b)
rule-columns-half-open = правило напіввідкритих стовпців (центри в [x_l, x_r): ліві ребра включаються, праві — ні)
rule-rows-half-open = правило напівінтервалу з книги (ребро враховується при min ≤ y < max)
rule-rows-closed = замкнені рядки BUET (min ≤ y ≤ max)
rule-rows-top-left = правило «верх-ліво» (ребро враховується при min < y ≤ max: верхні ребра включаються, нижні — ні)

explain-heading = піксель ({ $x }, { $y }) сцени { $file }: центр ({ $cx }; { $cy }), тест глибини { $test } ({ $rule })
polygon-line = { $polygon }: { $text }
explain-start = початок: буфер кадру { $frame }, z-буфер { $depth } (після очищення)
explain-final = підсумок: буфер кадру { $frame }, z-буфер { $depth }

check-all-match = { $buffer } { $file }: збігається з правильною відповіддю після { $after } (клітинок: { $cells })
check-differ = { $buffer } { $file }: { $count ->
    [one] відрізняється { $count } клітинка
    [few] відрізняються { $count } клітинки
   *[many] відрізняються { $count } клітинок
  } з { $cells } після { $after }
check-unanswered = ; без відповіді (? або .) { $count ->
    [one] залишено { $count } клітинку
    [few] залишено { $count } клітинки
   *[many] залишено { $count } клітинок
  } з { $cells }
check-hint-matches = підказка: якщо читати { $how }, відповідь збігається; записуйте спочатку верхній рядок (y = { $top }), кожен рядок від x = 0, як у книзі
check-hint-fewer = підказка: якщо читати { $how }, розбіжностей лишається: { $left }; записуйте спочатку верхній рядок (y = { $top }), кожен рядок від x = 0, як у книзі
check-column-answer = відповідь
check-column-right = правильно
check-column-why = чому
check-in-arith = в арифметиці { $arith } у клітинці { $mode }; у точній арифметиці { $exact }: { $reason }
grade-summary = клас { $class }, сцена { $scene }, після { $polygon }: { $students ->
    [one] { $students } студент
    [few] { $students } студенти
   *[many] { $students } студентів
  }; правильно: { $ok }, з помилками: { $wrong }, з непридатними файлами: { $malformed }, без відповіді: { $missing }
grade-column-student = студент
grade-column-frame = помилок у буфері кадру
grade-column-depth = помилок у z-буфері
grade-column-score = бали, %
grade-column-status = підсумок
grade-column-buffer = буфер
grade-column-wrong = помилилися
grade-column-answered = відповіді
grade-status-ok = правильно
grade-status-wrong = з помилками
grade-status-incomplete = не завершено: { $count ->
    [one] { $count } клітинку залишено
    [few] { $count } клітинки залишено
   *[many] { $count } клітинок залишено
  } без відповіді
grade-status-malformed = непридатний файл: { $why }
grade-status-missing = немає файлу: { $what }
grade-students-of = { $count } з { $total }
grade-mistakes = часті помилки (клітинки, у яких помилилися щонайменше двоє, спершу найчастіші):
grade-mistakes-none = часті помилки: у жодній клітинці не помилилися двоє чи більше
grade-feedback = { $student }: { $scene }, після { $polygon }: { $score } %, { $status }
exercise-title = вправа, seed { $seed }: растр { $width }×{ $height }, { $count ->
    [one] { $count } багатокутник
    [few] { $count } багатокутники
   *[many] { $count } багатокутників
  }
exercise-solution-title = вправа, seed { $seed }: буфер кадру після останнього багатокутника
exercise-task-draw = Намалюйте багатокутники по черзі (спершу A) алгоритмом z-буфера: що більше z, то ближче; z-буфер спочатку заповнений нулями й зберігає 0 … { $max } (з округленням і насиченням).
exercise-task-write = Запишіть буфер кадру (значення кожного багатокутника) і z-буфер після останнього багатокутника, починаючи з верхнього рядка.
misreading-upside-down = з нижнього рядка
misreading-transposed = по стовпцях (рядки й стовпці переставлено)

## run і step: заголовок сцени, етапи, заголовок багатокутника

depth-test-greater = більше
depth-test-less = менше
depth-test-greater-equal = більше або дорівнює
depth-test-less-equal = менше або дорівнює
depth-test-always = завжди
depth-test-never = ніколи
scene-header = сцена { $path }: { $width }×{ $height } пікселів, буфер кадру { $frame_bits } біт, z-буфер { $depth_bits } біт (0…{ $depth_max }), тест глибини { $test } ({ $rule }), після очищення { $clear }
scene-stages = етапи: { $stages }
scene-effects = ефекти: { $effects }
effects-none = немає
stage-cull = відкидання нелицьових граней (пропускаються багатокутники з обходом { $winding })
stage-near-plane = відсікання ближньою площиною (лишається z ≤ { $near }) і перспективна проєкція (око в z = { $eye })
stage-supersampling-sample = суперсемплінг { $k }×{ $k } (глибина в кожному відліку), потім усереднення
stage-supersampling-pixel = суперсемплінг { $k }×{ $k } (глибина в центрі пікселя), потім усереднення
stage-window = вікно { $left } … { $right } × { $bottom } … { $top } на растр
stage-scan = розкладання в растр
stage-scan-closed = розкладання в растр (замкнені рядки, клітинки з перетинами)
stage-scan-top-left = розкладання в растр (правило «верх-ліво»)
stage-depth-range = діапазон глибини (відкидаються z поза { $front } … { $rear })
stage-w-buffer = w-буфер (глибина в системі спостерігача z = d·z'/(d + z'))
stage-depth-test = тест глибини ({ $rule })
stage-section = переріз (z { $op } { $section })
stage-blend = змішування за непрозорістю (α·значення + (1 − α)·нижнє, половина округлюється вгору)
stage-store-quantized = запис (половина округлюється вгору, обмеження 0…{ $max })
stage-store-exact = запис (точна глибина)
heading-start = { $polygon } (значення { $value })
heading-degenerate = { $start }: вироджений: нормаль за Ньюелом нульова (вершини на одній прямій або петлі, що взаємно гасяться), тому він не має площини й не покриває жодного пікселя
heading-clipped-away = { $start }: за ближньою площиною: відсікається повністю, не малюється
heading-edge-on = { $start }: площина { $plane }: видно з ребра (c = 0), не покриває жодного пікселя
heading-culled = { $start }: площина { $plane }, { $winding }: відкидається як нелицьовий (cull { $cull }), не малюється
heading-drawn = { $start }: площина { $plane }{ $winding }{ $opacity }{ $clipped }
heading-drawn-projected = { $start }: площина після проєціювання { $plane }{ $winding }{ $opacity }{ $clipped }
heading-winding = { ", обхід " }{ $winding }
heading-opacity = { ", непрозорість " }{ $alpha }
heading-clipped = { "; " }перед ближньою площиною { $front } з { $of } вершин, малюється як { $n }-кутник
run-counts = покрито центрів пікселів: { $covered }, записано: { $written }
run-frame-after = буфер кадру після { $polygon }:
run-depth-after = z-буфер після { $polygon }:
run-no-polygons = у сцені немає багатокутників: буфери лишаються такими, як після очищення
run-frame-cleared = буфер кадру після очищення:
run-depth-cleared = z-буфер після очищення:
figure-title-worksheet = { $file }: багатокутники, які треба намалювати, на порожньому растрі
figure-title-after = { $file }: { $buffer } після { $polygon }
figure-title-samples = { ", " }по { $k }×{ $k } вибірок на піксель до усереднення (середні дає `zsim run`)
figure-cell = ({ $x }, { $y }): буфер кадру { $frame }, z-буфер { $depth }
figure-cells = ({ $from } … { $to }, { $y }): буфер кадру { $frame }
figure-background = { $value }: тло
figure-value = значення { $value }
figure-value-named = значення { $value }: { $names }
figure-polygons = багатокутників: { $count }
figure-axis-x = x (числа стоять біля центрів пікселів, x + ½)
figure-cleared = після очищення ({ $value })
figure-far = { $larger_nearer ->
    [yes] менше z: далі
   *[no] більше z: далі
}
figure-near = { $larger_nearer ->
    [yes] більше z: ближче
   *[no] менше z: ближче
}
file-written-about = записано { $path } ({ $about })
file-written-page = записано { $path } (відкрийте його в браузері; мережа не потрібна)

## step рядок за рядком

step-slope = уздовж рядка сканування z змінюється на −a/c = { $slope }
step-scanline = рядок сканування { $scanline } (рядок растра { $row })
step-crossings = перетини: { $list }
step-crossings-none = немає
step-span = відрізок { $n }: x_a = { $xa }, z_a = { $za }; x_b = { $xb }, z_b = { $zb }; { $columns }
step-columns = стовпці { $first } … { $last }
step-no-column = жодного стовпця
step-col-centre = центр
step-col-step = крок
step-col-stored = у z-буфері
step-col-test = тест
step-col-after = після
step-col-frame = кадр
step-start = початок
step-written = { $test }: записано
step-hidden = { $test }: прихований
step-test-written = { $z } { $op } { $stored }: записано
step-test-hidden = { $z } { $op } { $stored }: ні, прихований
step-beyond-section = { $op } { $stored }, за перерізом
step-outside-range = { $z }: поза діапазоном глибини, відкинуто
step-tie = граничний випадок при x = { $x }: { $text }
step-frame-after = буфер кадру після цього рядка (рядки { $low } … { $high }):
step-depth-after = z-буфер після цього рядка (рядки { $low } … { $high }):
step-end = кінець сцени: рядків більше немає (b назад, q вихід)
step-first = це вже перший рядок
step-outside-raster = рядок { $row } поза растром (рядки 0 … { $last })
step-not-reach = { $polygon } не сягає рядка сканування { $scanline }
step-unknown = невідома команда «{ $text }»; { $help }
step-prompt = { "zsim step> " }

## step у терміналі: повноекранний режим

tui-title = zsim step ·{ $heading } · { $view }{ $score } · ? клавіші
tui-heading = { " " }{ $polygon }, рядок сканування { $scanline }
tui-heading-end = { " кінець сцени" }
tui-score = { " · опитування " }{ $right }/{ $asked }
tui-key-nothing = ця клавіша тут нічого не робить: ? покаже клавіші
tui-no-later = жоден наступний багатокутник не покриває пікселів
tui-no-earlier = жоден попередній багатокутник не покриває пікселів
tui-go = перейти до рядка сканування ряду: { $text }▏ (Enter — перейти, Esc — скасувати)
tui-status = n/→ далі · b/← назад · p/P багатокутник · g перейти · f/z буфер · m по пікселях · q вихід
tui-no-scanline = немає рядка сканування
tui-columns-shown = x { $first } … { $last } з 0 … { $max }
tui-end = кінець сцени
tui-span = відрізок { $n }: { $left } … { $right }; { $columns }
tui-no-centre = жодного центру
tui-table-heading = x { $z } тест → у z-буфер (кадр)
tui-uncompared = { $test } пропускає,{ " " }
tui-not = { "не " }
tui-hidden = прихований
tui-pixel-by-pixel = m: по пікселях, з поясненнями
tui-steps-from = { ", " }кроків −a/c від { $start }: { $count }
tui-pixel = ({ $x }, { $y }): центр x = { $centre }, z = { $z }{ $steps }
tui-keys = { " клавіші " }
tui-help =
    n Space Enter → ↓  наступний рядок (або піксель)
    b ← ↑              назад
    p / P              наступний / попередній багатокутник
    g                  перейти до рядка сканування ряду
    f / z              показати буфер кадру / z-буфер
    m                  по пікселях / по рядках
    PgUp PgDn < >      прокрутити растр
    { "[ ]" }                прокрутити таблицю
    ?                  ці клавіші (будь-яка клавіша закриває)
    q Esc Ctrl-C       вихід

    жовтим: покриті пікселі відрізка
    блакитним: попередні записи цього багатокутника

## опитування (step --quiz)

quiz-mistakes = ваші помилки:
meant-not-written = не записується
meant-value-written = записане значення
meant-value-kept = не записується: значення, що залишається
meant-value = значення
quiz-coverage-hint = введіть покриті стовпці як перший-останній (кілька відрізків через пробіл: 3-5 9-12) або -, якщо жодного
quiz-coverage-why = відрізки: { $spans }; стовпець покритий, якщо його центр x + 1/2 лежить в одному з них
quiz-coverage-mistake = рядок { $row } { $polygon }: ваша відповідь — стовпці { $said }, правильно { $right }: { $why }
quiz-depth-hint = введіть значення, яке буде в z-буфері, або - якщо не записується (q завершує опитування)
quiz-not-an-answer = «{ $text }» — не відповідь: { $hint }
quiz-does-not-fit = { $text } не вміщується в цей z-буфер: його комірки зберігають цілі рівні 0 … { $max }; введіть знову
quiz-keeps = - (залишається { $value })
quiz-depth-mistake = ({ $x }, { $y }) { $polygon }: ваша відповідь { $said }, правильно { $right }: { $reason }

## step --html: сторінка

page-back = ◀ Назад (b)
page-next = Далі ▶ (n)
page-previous-polygon = ◀◀ Багатокутник (P)
page-next-polygon = Багатокутник ▶▶ (p)
page-frame = Буфер кадру (f)
page-depth = Z-буфер (z)
page-quiz = опитування
page-no-pixel = Ця сцена не покриває жодного пікселя.
page-frame-after = буфер кадру після цього рядка
page-depth-after = z-буфер після цього рядка
page-column-stored = було
page-column-after = z-буфер після
page-column-why = чому
page-keeps = – (залишається { $value })
page-check = Перевірити відповіді
page-status = рядок { $at } з { $count }

## помилки, які найчастіше трапляються студентові: файли, багатокутники, відповіді

error-read = { $path }: не вдається прочитати: { $reason }
error-write = { $path }: не вдається записати: { $reason }
error-polygon = { $path }: { $polygon }: { $problem }
geometry-too-few = вершин { $count }; багатокутник мусить мати щонайменше 3
geometry-too-many = вершин { $count }; zsim приймає щонайбільше { $max }
geometry-out-of-range = у вершини { $vertex } координата { $value } поза точним діапазоном: за спільного знаменника багатокутника { $denominator } |координата| × 2 × { $denominator } має бути не більшою за 2^4096 (візьміть менші координати або менше знаків після коми)
digits = { $count } цифр
geometry-off-plane-z = не плоский: вершина { $vertex } відстоїть від площини { $plane }, проведеної через вершини { $i }, { $j }, { $k }, на Δz = { $off }
geometry-off-plane = не плоский: вершина { $vertex } дає { $off } замість 0 у рівнянні площини { $plane }, проведеної через вершини { $i }, { $j }, { $k }
answer-at-cell = рядок { $line }, число { $column } (x = { $x }, y = { $y })
answer-at = рядок { $line }, число { $column }
answer-not-a-number = { $at }: «{ $cell }» — не ціле число ({ $buffer } зберігає 0 … { $max })
answer-too-large = { $at }: { $value } не вміщується в { $buffer } (0 … { $max })
answer-row-length = рядок { $line }: { $count ->
    [one] { $count } число
    [few] { $count } числа
   *[many] { $count } чисел
  }, а ширина растра { $width }
answer-row-count = рядків { $count }, а в растра їх { $height }
answer-frame-range = { $bits }-бітний буфер кадру
answer-depth-range = { $bits }-бітний z-буфер

## доповнення explain: переріз, сегменти, перевірки «всередині», згладжування, інша арифметика

explain-section = переріз: записуються лише z { $op } { $section }
explain-inside = перевірки «всередині» для центру: трасування променя — { $ray }; сума кутів — { $arc }
explain-inside-in = всередині
explain-inside-out = зовні
explain-arc-boundary = на межі, отже всередині
explain-arc-winding = число обертів { $winding }, отже { $inside }
explain-segment = сегмент { $number } з { $count } ({ $segments }): стовпці { $first } … { $last }, рядки { $bottom } … { $top }; його z-буфер зберігає клітинок: { $cells }; його зачіпають: { $visited }
explain-segment-none = жоден багатокутник
explain-antialias = згладжування за сіткою відліків { $k }×{ $k } (рядки вище — центр пікселя без згладжування; рядки відліків рахують в 1/{ $k } пікселя)
explain-sample = відлік ({ $i }, { $j }) у точці ({ $x }; { $y }): буфер кадру { $frame }, z-буфер { $depth }
explain-pixel-mode = { $polygon } покриває відліки { $samples }; глибина його площини в центрі пікселя { $depth }: { $result }
explain-pixel-mode-written = записано, у z-буфері { $stored }, і ці відліки отримують значення
explain-pixel-mode-not-written = не записано
explain-mean = середнє за відліками: буфер кадру { $frame }, z-буфер { $depth }
explain-arith = в арифметиці { $arith }: буфер кадру { $frame }, z-буфер { $depth } ({ $verdict })
explain-arith-same = як у точній
explain-arith-differs = не те, що дає точна арифметика

## вершини в просторі відсікання [x, y, z, w]

vertex-decimal-comma = у вершині чотири числа, { $written }, серед вершин [x, y, z]: { $comma } — це десяткова кома? У JSON дробову частину відділяє крапка: напишіть { $meant }
clip-space-mixed = змішує вершини [x, y, z] з вершинами [x, y, z, w] у просторі відсікання: запишіть усі вершини багатокутника однаково
clip-space-alone = заданий вершинами [x, y, z, w] у просторі відсікання, які переносить на растр перетворення області виведення; вони не поєднуються з вікном і з ефектом перспективи
fate-outside-view = він поза видимим об'ємом (−w ≤ x, y, z ≤ w): відсікається повністю й не малюється
heading-outside-view = { $start }: поза видимим об'ємом (−w ≤ x, y, z ≤ w): відсікається повністю, не малюється
heading-view = { "; простір відсікання: " }усередині видимого об'єму { $inside } з { $of } вершин, після відсікання, ділення на w та області виведення малюється як { $n }-кутник

## читання сцени

scene-not-object = сцена — це JSON-об'єкт на кшталт {"{"}"width": 32, "height": 32, "polygons": [...]{"}"}, а не { $found }
json-array = масив
json-string = рядок
json-number = число
json-bool = true або false
json-null = null
json-comma-end = { " (наприкінці рядка " }{ $line } бракує коми)
json-comma-after = { " (бракує коми після рядка " }{ $line }, позиції { $column })
json-invalid = це не коректний JSON: { $error }
location-polygon = багатокутник { $number }
number-found-object = очікувалося число, а знайдено об'єкт
number-found-bool = очікувалося число, а знайдено логічне значення
number-found-null = очікувалося число, а знайдено null
number-found-list = очікувалося число, а знайдено список
number-not-a-number = «{ $text }» — не число (запишіть ціле, десятковий дріб на кшталт 2.5 або дріб на кшталт "5/2")
number-zero-denominator = «{ $text }» — ділення на нуль
number-too-large = у «{ $text }» забагато цифр, щоб зберігати точно (не більше 30 значущих цифр)
number-too-long = у «{ $text }» забагато цифр або завелика степінь десяти (координата вершини має не більше { $max } значущих цифр і степені десяти не більше ±{ $max })
setting-bits = { $value } не підтримується: допустимо від 1 до 32 біт
setting-side-zero = має бути щонайменше 1 піксель
setting-side-large = { $side } перевищує межу в { $max } пікселів
setting-cells = { $width }×{ $height } — це { $cells } пікселів, більше за межу { $max }
setting-background = { $value } не вміщується в { $bits }-бітний буфер кадру (щонайбільше { $max })
setting-window = ліва межа { $left } має бути меншою за праву { $right }, нижня { $bottom } — меншою за верхню { $top }
setting-depth-range = [{ $front }, { $rear }]: передня межа не має перевищувати задню
setting-clear-depth = застосовується лише до точного z-буфера (правила з "store": "exact"); квантований очищається до найдальшого рівня
setting-perspective-positive = перспектива: distance і near мають бути додатними
setting-antialias-samples = згладжування: { $samples } відліків не підтримується: допустимо від 1 до 16
setting-antialias-cells = згладжування: { $width }×{ $height } пікселів × { $samples }² відліків перевищує межу в { $max } клітинок
setting-antialias-exact = згладжування усереднює квантований z-буфер; з точним зберіганням воно не поєднується
polygon-opacity = непрозорість { $alpha } поза діапазоном 0 … 1
polygon-value-too-wide = значення { $value } не вміщується в { $bits }-бітний буфер кадру (не більше за { $max })

origin-supersampled = сцена із суперсемплінгом { $factor }×
origin-snapped = сцена, прив'язана до fixed:{ $bits }

usage-arith-plain-rules = --arith { $arith } моделює простий алгоритм за правилами підручника; ця сцена потребує інших правил або попіксельних ефектів (використайте --arith exact)
usage-arith-greater-or-less = --arith { $arith } моделює тести глибини greater і less; ця сцена потребує { $test } (використайте --arith exact)
usage-arith-plain-loop = --arith, відмінний від exact, виконує простий цикл z-буфера; приберіть --segments і --order
usage-no-polygon-numbered = багатокутника { $number } немає: у сцені їх { $count } (нумерація з 1)
usage-no-polygon-named = багатокутника з назвою «{ $name }» немає: у сцені є { $names }
usage-pixel-outside = піксель ({ $x }, { $y }) лежить поза растром { $width }×{ $height } (x 0 … { $last_x }, y 0 … { $last_y })
usage-figure-format = { $path }: рисунок записується як .svg, .png, .pdf або .tex (TikZ)
usage-figure-too-large = { $path }: рисунок будується для растрів до { $max }×{ $max }; цей растр { $width }×{ $height }
usage-png-failed = { $path }: не вдається побудувати рисунок: { $reason }
usage-no-polygons-draw = { $path }: у сцені немає багатокутників для малювання
usage-no-polygons-grade = { $path }: у сцені немає багатокутників для оцінювання
usage-no-polygons-check = { $path }: у сцені немає багатокутників для перевірки
usage-exact-depths-grade = { $path }: ця сцена зберігає точні глибини, тож її z-буфер не має цілочислової матриці для оцінювання; оцінюйте буфери кадру
usage-exact-depths-check = { $path }: ця сцена зберігає точні глибини, тож її z-буфер не має цілочислової матриці для перевірки; перевірте буфер кадру або z_buffer.txt курсу BUET командою `zsim buet check`
usage-check-needs-answer = для перевірки потрібна відповідь: --frame ФАЙЛ і/або --depth ФАЙЛ
usage-no-answers = { $path }: відповідей не знайдено: назвіть файли кожного студента ІМ'Я.frame.txt і/або ІМ'Я.depth.txt
usage-scenes-range = --scenes приймає від 1 до 100
usage-memory-bits = { $option } { $bits }: допускається від 1 до 64 бітів
usage-memory-zero = --width, --height і --supersample мають бути не менші за 1
usage-memory-too-large = растр завеликий для підрахунку (понад 2^50 комірок)
usage-random-count = --count { $count }: не більше { $max } трикутників (сцену такого розміру читати назад близько 10 ГБ)
usage-random-bits = --frame-bits і --depth-bits приймають від 1 до 32
usage-random-side = --width і --height приймають від 1 до { $max }
usage-not-a-hard-case = --hard: «{ $name }» — не складний випадок: { $names }
usage-exercise-size = --size { $width }x{ $height }: вправа має від 4 до 64 пікселів на сторону
usage-exercise-polygons = --polygons { $count }: у вправі від 1 до 8 багатокутників
usage-exercise-bits = для вправи вручну --frame-bits приймає від 1 до 8, а --depth-bits від 1 до 16
usage-exercise-two-polygons = для hidden та intersecting потрібні два багатокутники або більше (--polygons 2)
usage-exercise-not-found = за { $tries } спроб не знайшлося сцени з { $polygons } багатокутників на растрі { $width }×{ $height } з усіма випадками { $cases }; попросіть менше випадків, більше багатокутників або більший растр
usage-inside-needs-pixel-order = --inside вибирає тест «точка в багатокутнику» для --order pixels; додайте --order pixels
usage-tiles-need-format-none = --tile і --threads стосуються --format none, --final і --after (інакше показується стан після кожного багатокутника, намальованого по черзі)
usage-format-none-is-plain = --format none підсумовує цикл z-буфера; із --segments, --order pixels або згладжуванням використовуйте text або json
usage-no-scanlines = { $polygon } не має рядків сканування: { $why }
usage-scanline-rows = { $reach }: його рядки { $first } … { $last }
usage-scanline-no-rows = { $reach }: він не сягає жодного рядка растра

step-skip-fate = { $polygon }: { $why }
step-skip-no-scanline = { $polygon }: не сягає жодного рядка сканування растра
step-skip-no-centre = { $polygon }, рядок сканування { $scanline }: не покрито жодного центру пікселя
step-skip-no-centre-no-crossings = { $polygon }, рядок сканування { $scanline }: не покрито жодного центру пікселя (перетинів немає)

case-line = рядок { $line }: { $problem }
case-unknown-command = невідома команда «{ $command }»
case-keyword-problem = { $keyword }: { $problem }
list-or = { $rest } або { $last }
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
cs418-texture-unreadable = не вдається прочитати ({ $reason })
cs418-image-size = зображення { $width } × { $height }, а завдання малює { $case_width } × { $case_height }
png-not-an-image = не зображення PNG ({ $reason })
png-too-large = PNG завеликий
png-broken = пошкоджене зображення PNG ({ $reason })
png-colour-type = неочікуваний колірний тип PNG { $kind }
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

rules-describe = правила { $preset }: { $rows }; { $columns }; { $store }
rules-rows-half-open = рядки напіввідкриті (min ≤ y < max), перетини попарно
rules-rows-closed = рядки замкнені (min ≤ y ≤ max), один відрізок від найменшого до найбільшого перетину
rules-rows-top-left = рядки «згори-зліва» (min < y ≤ max: центри на верхньому ребрі входять, на нижньому ні), перетини попарно
rules-columns-centre-inside = стовпці, чий центр лежить у відрізку
rules-columns-cell-holds = стовпці від комірки з x_a до комірки з x_b
rules-columns-half-open = стовпці, чий центр лежить у [x_l, x_r): центри на лівому ребрі входять, на правому ні
rules-store-quantized = глибина округлюється вгору на половині й насичується
rules-store-exact = глибина зберігається точно

place-vertex-on-scanline = багатокутник { $polygon }: вершина { $vertex } ({ $x }; { $y }) лежить на рядку сканування ряду { $row }
place-centre-on-edge = піксель ({ $x }, { $y }): його центр лежить на ребрі багатокутника { $polygon }
place-spans = багатокутник { $polygon }: у ряду { $row } відрізків: { $spans }
place-half-depth = піксель ({ $x }, { $y }), багатокутник { $polygon }: z = { $z } округлюється вгору до { $stored }
place-saturation = піксель ({ $x }, { $y }), багатокутник { $polygon }: z = { $z } округлюється до { $rounded }, зберігається { $stored }
place-hidden = піксель ({ $x }, { $y }), багатокутник { $polygon }: z = { $z } не проходить тест проти збереженого { $stored }
place-intersecting = багатокутники { $first } і { $second }: кожен десь перед іншим

cs418-elements-range = drawElementsTriangles { $count } { $offset } читає елементи { $offset }…{ $last }, а в «elements» їх { $has }
cs418-point-size-range = drawArraysPoints читає розмір точки { $index }, а в «pointsize» їх { $has }
cs418-texcoord-range = вершина { $index } малюється з текстурою, а в «texcoord» вершин { $has }
cs418-too-far = вершина потрапляє в ({ $x }, { $y }) на зображенні, надто далеко від нього для растеризації (далі { $reach } розмірів зображення): увімкніть «frustum», щоб відсікти її
cs418-too-many-primitives = { $count } примітивів не вміщуються в 32-бітний буфер кадру

file-written = записано { $path }
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
file-written-in = записано { $files } у { $path }
exercise-notes-settings = вправа: зерно { $seed }, растр { $width }×{ $height }, багатокутників { $polygons }, буфер кадру { $frame_bits } біт, z-буфер { $depth_bits } біт (0 … { $max }), тест глибини { $test }
exercise-notes-asked = замовлено: { $asked } (кандидат { $candidate } з послідовності зерна)
exercise-notes-no-case = жодного особливого випадку
exercise-notes-contains = містить (знайдено в трасі прогону, перше місце кожного):
exercise-notes-none = жодного складного випадку
exercise-notes-next = перевірити відповідь: zsim check { $path } --frame FRAME.txt --depth DEPTH.txt; оцінити групу: zsim grade { $path } CLASS_DIR
png-no-fonts = у цій системі немає шрифтів, і текст зник би; запишіть SVG (-o FILE.svg)
png-figure-too-large = рисунок завеликий
error-output = не вдається записати вивід: { $reason }
memory-header-buffer = буфер
memory-header-cells = комірок
memory-header-bits-per-cell = бітів на комірку
memory-header-bits = бітів
memory-header-bytes = байтів
memory-total = усього
memory-at-sample = відліку
memory-at-pixel = пікселі
memory-supersampled = , суперсемплінг { $k }×{ $k } з глибиною в кожному { $at }
memory-heading = { $width }×{ $height } пікселів, буфер кадру { $frame_bits } бітів, z-буфер { $depth_bits } бітів{ $sampling }
memory-total-line = усього: { $total } байтів = { $megabytes }
step-antialias-note = примітка: ця сцена потребує суперсемплінгу { $k }×{ $k }; step показує просте покриття й глибину кожного центру пікселя до суперсемплінгу й усереднення (`zsim run` показує усереднені буфери, `zsim explain --pixel X,Y` — відліки кожного пікселя)
step-fixed = в арифметиці fixed:{ $bits } вершини спершу прив'язуються до кратних 1/{ $unit }, потім ці точні правила працюють із прив'язаним багатокутником (`zsim run --arith fixed:{ $bits }` показує результат)
step-float-exact = точно { $z }
step-float-not-exact = точна арифметика його не покриває
step-float-edges = реберні функції в центрах стовпців обмежувального прямокутника { $first } … { $last }
step-float-no-crossings = перетинів немає
step-float-crossings = перетини { $crossings }
step-float-heading = в арифметиці { $arith }: { $found }
step-float-no-pixel = жоден піксель не покрито
step-float-missed = пропущено точні центри x = { $columns }
run-summary = { $path }: багатокутників { $polygons }, перевірено центрів пікселів: { $tested }, записано: { $written }; ефекти: { $effects }; стадії: { $stages }; читання { $read } мс, растеризація { $raster } мс, потоків: { $threads } ({ $rate } млн пікселів/с); пам'ять: буфери { $buffers }, сцена { $scene }{ $peak }
run-summary-peak = , пік резидентної пам'яті { $peak }
run-summary-peak-ratio = , пік резидентної пам'яті { $peak } ({ $ratio }× буфери + сцена)
run-summary-no-effects = немає
run-summary-arith = ; арифметика { $arith }
run-arith-compared = арифметика: { $arith }; порівняно з точною арифметикою відрізняються комірок буфера кадру: { $frame }, z-буфера: { $depth }
run-frame-after-all = буфер кадру після всіх багатокутників:
run-depth-after-all = z-буфер після всіх багатокутників:
compare-rules-this = у цій сцені { $rules }
compare-rules-other = для порівняння: { $rules }
compare-rules-same = усі пікселі виходять однаковими: жоден центр не лежить точно на ребрі, де правила розходяться
compare-rules-differ = пікселів, що відрізняються: { $count }:
compare-rules-nothing = нічим
compare-rules-cell = ({ $x }, { $y }): { $before } → { $after }; покритий { $covering } за { $rules }, { $other_covering } за { $other_rules }
compare-rules-vertex = центр ({ $x },5, { $y },5) — вершина { $vertex } багатокутника «{ $name }»: вирішують ребра, що в ній сходяться, за кожним набором правил як на самих ребрах
compare-rules-edge = центр ({ $x },5, { $y },5) лежить на ребрі ({ $boundary }) багатокутника «{ $name }» від { $from } до { $to }: { $verdict } за { $rules }, { $other_verdict } за { $other_rules }
compare-rules-covered = покритий
compare-rules-left-out = не покритий
preset-rogers = правилами підручника
preset-buet = правилами BUET
preset-gl = правилом OpenGL
preset-vulkan = правилом «згори-зліва» Vulkan і Direct3D
variant-identical = збігається з простим z-буфером (буфер кадру й z-буфер)
variant-differs = відрізняються від простого z-буфера комірок: { $count }
variant-result = результат: { $result }
segments-kind = сегменти: { $count } ({ $segments }), кожен багатокутник віднесено до сегментів, яких торкається його обмежувальний прямокутник
segments-memory = пам'ять z-буфера: { $cells } комірок × { $bits } бітів = { $total } бітів (весь растр: { $whole_cells } комірок, { $whole_bits } бітів)
segments-visits = відвідин багатокутників: { $visits } (весь растр: { $whole })
pixel-order-ray = трасування променя (правило вершин «ліворуч відкрито, праворуч замкнено»; межа рахується)
pixel-order-arc = метод довжини дуги (таблиця квадрантів; межа рахується)
pixel-order-heading = порядок: для кожного пікселя, для кожного багатокутника, одна змінна глибини (китайський конспект); тест належності: { $test }
pixel-order-header-polygon = багатокутник
pixel-order-header-why = чому тести належності розходяться
pixel-order-on-boundary = центр лежить точно на межі: дуга вважає його внутрішнім, а правило півінтервалу не включає верхні ребра й вершини (ребро рахується лише біля нижнього кінця)
pixel-order-winding = багатокутник обходить центр { $winding } разів: дуга вважає ненульову кількість обертів внутрішньою, парні перетини (парність) — зовнішньою
pixel-order-disagree = центрів, де дуга й правило рядків сканування розходяться: { $count }
antialias-at-sample = відліку
antialias-at-centre = центрі пікселя
antialias-heading = згладжування: { $k }×{ $k } відліків на піксель, глибина в кожному { $at }; значення — середні за відліками (частки від { $samples })
antialias-frame-after = буфер кадру після { $polygon }, усереднений:
antialias-depth-after = z-буфер після { $polygon }, усереднений:
transparency-all-match = прозорість: кожна комірка збігається з правильним змішуванням від дальнього до ближнього
transparency-header-drawn = намальовано
transparency-header-back-to-front = від дальнього до ближнього
transparency-header-polygons = багатокутники там, від дальнього до ближнього
transparency-differs = прозорість: комірок, що відрізняються від правильного змішування від дальнього до ближнього: { $count } (локальні помилки малювання в неправильному порядку: багатокутник за прозорим, намальований після нього, не проходить тест глибини):
accuracy-header-mode = режим
accuracy-header-ns = нс на піксель
accuracy-header-pixels = пікселів
accuracy-header-frame = комірок кадру ≠ точно
accuracy-header-depth = комірок глибини ≠ точно
accuracy-header-worst = найбільша помилка глибини (рівнів)
accuracy-header-time = час до точного
accuracy-header-bits = бітів глибини
accuracy-header-fighting = комірок z-конфлікту
accuracy-header-memory = пам'ять z-буфера (байтів)
accuracy-header-ms = час (мс)
accuracy-set = набір для точності: { $scenes } сцен на { $width }×{ $height } (випадкові трикутники в 4, 16, 64 і 256 пікселів із вершинами на сітці 1/256, зерно { $seed }, і 4 складні випадки); час режиму — найменший із 5 кіл, у кожному з яких режими працюють по черзі
accuracy-sweep = дві майже компланарні площини, що перетинаються по x = y (світові глибини 0 … 1, помножені на 2^bits рівнів; нахил 1/2^20 діапазону на піксель), { $cells } комірок:
progress-bands = смуг плиток
progress-polygons = багатокутників

# Inputs zsim refuses before reading.
error-not-regular = { $path }: не звичайний файл (це { $kind }): zsim читає лише звичайні файли
error-too-large = { $path }: більший, ніж читає zsim ({ $limit } МіБ)
file-kind-directory = тека
file-kind-fifo = іменований канал (FIFO)
file-kind-device = пристрій
file-kind-socket = сокет
file-kind-link = символічне посилання, за яким zsim не переходить
file-kind-other = не звичайний файл
error-not-utf8 = не текст у UTF-8
usage-output-is-input = { $path } — один із входів, які читає zsim: запишіть вивід в інше місце
usage-output-would-replace = у { $path } вже є { $files }{ $more ->
    [0] {""}
   *[other] { " " }і ще { $more }
}: zsim не замінює файли; виберіть нову або порожню теку
usage-tile-zero = --tile приймає 1 піксель і більше (з 0 нічого не малюється)
stdout-closed = стандартний вивід закрито
buet-look-at-eye = точка, куди дивляться, збігається з положенням ока: погляд не має напрямку
buet-up-along-view = напрямок угору нульовий або лежить уздовж напрямку погляду: камера не має орієнтації
buet-perspective = fovY і fovY·aspect мають лежати між 0 і 180 градусами, aspect і near бути додатними, а far відрізнятися від near
buet-rotation-axis = поворот навколо осі 0 0 0 не має напрямку
token-cut = { $shown }… ({ $count } символів)

# The machine's OpenGL.
gpu-no-library = OpenGL не знайдено: { $reason } (установіть libegl1 libegl-mesa0 libgl1-mesa-dri)
gpu-refused = OpenGL відмовив у { $step }: { $reason }
gpu-heading = { $path }, намальований { $renderer }, поруч із zsim за правилами сцени й за набором { $preset }
gpu-same = кожен піксель показує той самий багатокутник на GPU і в zsim
gpu-differ = пікселів з іншим багатокутником: { $count }:
gpu-cell = ({ $x }, { $y }): GPU показує { $gpu }; zsim показує { $book } за правилами сцени, { $covered } за { $preset }
gpu-background = нічого
gpu-exact-depth = { $polygon } на точній глибині { $depth }
gpu-why-depth = GPU записав глибину { $gpu } (інтерполяція в f32, зберігання в 24 бітах) для { $shown }; за правилами сцени лишається { $book }
gpu-not-convex = примітка: { $polygon } не опуклий: GPU малює його віялом трикутників із першої вершини, а це не той багатокутник
speed-header = { $scene }: трикутників { $triangles } (віяла { $polygons } многокутників{ $skipped ->
    [0] {""}
   *[other] ; ще { $skipped } нічого не малюють: вироджені, видні з ребра, відсічені або поза полем зору
  }), перевірено центрів пікселів { $pixels }; zsim на { $threads } { $threads ->
    [one] потоці
   *[other] потоках
}, { $tile ->
    [0] полігон за полігоном
   *[other] плитками по { $tile }
}, проти { $renderer } (LP_NUM_THREADS={ $lp }), { $pairs } пар по черзі після одного неврахованого прогону кожного
speed-result = zsim { $zsim } мс, GPU { $gpu } мс (медіани): zsim витрачає { $ratio }× часу GPU (у парах від { $low }× до { $high }×)
speed-fresh = увесь прогін zsim у нових буферах, як малює `zsim run`: { $fresh } мс (медіана), { $ratio }× часу GPU
speed-memory = zsim перевіряв { $rate } млн центрів пікселів за секунду; копія { $megabytes } МБ буферів зайняла { $copy } мс ({ $bandwidth } ГБ/с), що при { $bytes } байтах на піксель, прочитаних і записаних по разу, дозволяє { $limit } млн пікселів за секунду
usage-compare-gpu-plain = --compare-gpu порівнює простий алгоритм: ця сцена потребує попіксельних ефектів або згладжування
usage-no-gpu = --compare-gpu: { $reason }
gpu-why-depth-unread = GPU показує { $shown }; за правилами сцени лишається { $book } (вирішили глибини: GPU інтерполює їх у f32)
gpu-no-vulkan = пристрій Vulkan не знайдено: { $reason } (установіть mesa-vulkan-drivers)
gpu-not-built = цей zsim зібрано без можливості { $feature }: зберіть його командою `cargo install --path . --features { $feature }`

## What the system and the JSON reader say (words/system.rs)
io-not-found = немає такого файлу чи теки
io-permission-denied = немає доступу
io-already-exists = він уже існує
io-is-a-directory = це тека
io-not-a-directory = частина шляху — не тека
io-storage-full = диск заповнений
io-read-only = файлова система лише для читання
io-not-utf8 = файл — не текст у UTF-8
json-at = { $message } (рядок { $line }, позиція { $column })
json-invalid-type = неправильний тип: знайдено { $found }, а очікувався { $expected }
json-invalid-value = неправильне значення: знайдено { $found }, а очікувався { $expected }
json-invalid-length = елементів: { $length }, а очікувався { $expected }
json-missing-field = немає поля { $field }
json-unknown-field = невідоме поле { $field }; можливі поля: { $known }
json-unknown-field-none = невідоме поле { $field }
json-unknown-variant = невідоме значення { $variant }; можливі значення: { $known }
json-duplicate-field = поле { $field } задано двічі
json-eof = файл обривається посеред значення
json-expected-token = очікувався символ { $token }
json-expected-value = очікувалося значення
json-trailing = після кінця сцени є ще текст
json-trailing-comma = кома перед закривною дужкою
json-key-string = ключ має бути рядком у лапках
json-invalid-number = неправильне число
json-number-range = число поза допустимим діапазоном
json-invalid-escape = неправильна escape-послідовність у рядку
json-too-deep = занадто глибока вкладеність
json-control = керівний символ усередині рядка
json-found-integer = ціле число { $value }
json-found-decimal = десяткове число { $value }
json-found-string = рядок { $value }
json-found-bool = { $value }
json-found-null = null
json-found-list = список
json-found-object = об'єкт
json-want-list = список
json-want-string = рядок
json-want-bool = true або false
json-want-number = число (або рядок із дробом чи десятковим числом)
json-want-vertex = вершина [x, y, z] (або [x, y, z, w] у просторі відсікання)
json-want-object = об'єкт
json-want-whole = ціле число
usage-pixel-not-xy = «{ $text }» — не X,Y (наприклад, 20,15)
usage-pixel-coordinate = «{ $text }» — не координата пікселя
usage-arith = «{ $text }» — не режим арифметики: `exact`, `f64`, `f64-incremental`, `f32-incremental`, `f32`, `f32-edge` або `fixed:K` (K від 0 до 24)
usage-missing = бракує: { $args }
usage-invalid-value = «{ $value }» не підходить для { $arg }: { $reason }
usage-unknown-argument = невідомий параметр { $arg }
usage-unknown-command = невідома команда { $name }
usage-conflict = { $arg } не можна задавати разом із { $other }
usage-see-help = довідка: zsim --help

## The misconception behind a wrong answer (teach/diagnose.rs)
diagnosis = імовірна причина: { $what } (пояснює { $explained } з { $wrong } { $wrong ->
    [one] неправильної клітинки
   *[other] неправильних клітинок
})
misconception-truncated = глибини відкинуто до цілого (округлено вниз), а не округлено до найближчого цілого
misconception-half-down = половини округлено вниз, а не вгору (10,5 записано як 10)
misconception-rounded-compared = із z-буфером порівнювали округлену глибину, а не точне z
misconception-no-saturation = глибини поза діапазоном z-буфера переповнилися по колу, а не наситилися
misconception-not-strict = рівну глибину пропущено (≥ замість >)
misconception-reversed = тест глибини перевернуто (ближчим вважали менше z)
misconception-last-only = намальовано лише останній багатокутник
misconception-one-early = відповідь на один багатокутник раніше
misconception-bottom-first = рядки записано починаючи з нижнього
misconception-corners = пікселі взято в кутах, а не в центрах
misconception-cell-rule = стовпці взято за клітинками, у які потрапляють кінці відрізка, а не за центрами всередині відрізка
grade-column-cause = імовірна причина
grade-cause = { $what } ({ $explained } з { $wrong })
grade-causes = імовірні причини в групі:
grade-cause-count = { $what }: { $count } з { $students } { $students ->
    [one] студента
   *[other] студентів
}
answer-more-problems = { "" } · і ще { $count } { $count ->
    [one] помилка
    [few] помилки
   *[many] помилок
}
usage-no-submission = { $folder }: тут немає відповіді: frame.txt, depth.txt, after-N.frame.txt або after-N.depth.txt
gradescope-test = { $buffer } після { $after }
usage-identity-column = --identity: ця платформа не імпортує за стовпцем «{ $column }» (Moodle: email, idnumber, username; Canvas: id, sis-user-id, sis-login-id)
usage-no-points = --points має бути не менше 1
figures-not-built = цей zsim зібрано без рисунків { $format } (можливість figures, вимкнена у звичайній збірці): зберіть його командою `cargo install --path . --features figures`; у пакеті Debian вони є. Рисункам SVG і TeX нічого не потрібно

## tinyrenderer's OBJ files (courses/tinyrenderer.rs)
obj-vertex-count = у вершини мають бути x, y і z; у цьому рядку чисел: { $count }
obj-not-a-number = «{ $token }» — не число
obj-face-corners = у грані уроку 3 вершини; у цієї: { $count }
obj-bad-index = «{ $token }» — не номер вершини (з 1)
obj-too-many-faces = понад { $max } граней
obj-no-vertex = вершини { $index } немає: у файлі їх { $count }
rules-store-truncated = глибина відкидається до цілого (округлюється вниз) з насиченням
rules-sample-corner = ; вибірка в цілих точках (x, y), кутах пікселів
rules-compare-level = ; порівнюється глибина, округлена так само, як записується
rules-min-area = ; багатокутники з орієнтованою площею меншою за { $area } пропускаються
stage-store-truncated = запис (відкидання дробової частини, насичення до 0…{ $max })
preset-tinyrenderer = урок tinyrenderer про z-буфер
fate-small-area = його орієнтована площа менша за межу правил (зворотна грань або скалка): його пропущено
heading-small-area = { $start }: площина { $plane }, пропущено (орієнтована площа менша за межу правил: зворотна грань або скалка)
tinyrenderer-run = { $model }: граней { $faces }, пропущено { $skipped } (площа менша за 1), намальовано { $drawn }; записано zbuffer.tga і framebuffer.tga в { $folder }
tinyrenderer-differ = точна арифметика дає інший рівень z-буфера, ніж f64 уроку, у { $count } { $count ->
    [one] пікселі
   *[other] пікселях
}
tinyrenderer-differ-pixel = ({ $x }, { $y }), грань { $face }: f64 { $float }, точно { $exact } (інтерпольоване z ціле; f64 трохи менше, і відкидання дробової частини втрачає рівень)
tinyrenderer-line = рядок { $line }
explain-others = ще { $count } багатокутників не доходять до рядка сканування цього пікселя: { $skipped } не малюються взагалі (пропущені, відсічені або видимі з ребра), у { $off } рядки лежать деінде
explain-corner-sample = за правилами вибірку беруть у цілій точці ({ $x }, { $y }): zsim малює сцену, зсунуту на ½, щоб цей центр був цією точкою, і координати нижче — зсунуті
stored-truncated = в z-буфер записується { $stored } ({ $value } без дробової частини — { $stored })
stored-truncated-saturated = в z-буфер записується { $stored } ({ $value } без дробової частини, з насиченням до { $stored })
usage-tinyrenderer-size = «{ $text }» — не сторона зображення: { $min } … { $max } пікселів
quiz-frame-hint = введіть значення, яке буде в буфері кадру, або - якщо не записується (q завершує опитування)
quiz-frame-does-not-fit = { $text } не вміщується в цей буфер кадру: його комірки зберігають цілі значення 0 … { $max }; введіть знову
usage-not-a-preset = «{ $text }» — не набір правил: використовуйте rogers, buet, gl, vulkan (d3d, webgpu) або tinyrenderer
error-outside-folder = { $path }: ім'я всередині файлу має лишатися в теці цього файлу ({ $folder }): без «..» і без абсолютного шляху
usage-output-name-too-long = { $path }: ім'я довше, ніж допускають файлові системи ({ $max } байтів); нічого не записано
usage-output-twice = { $path } було б записано однією командою двічі; нічого не записано
png-declares-too-many-pixels = PNG оголошує { $width } × { $height } пікселів, більше, ніж декодує zsim ({ $max })
cs418-too-many-samples = fsaa { $level } потребує { $samples } відліків, більше, ніж малює zsim ({ $max }): зменште fsaa або розмір зображення
usage-same-answer-twice = { $path }: { $files } відповідають за той самий буфер того самого стану: здайте один
expect-not-states = «{ $text }» — не список станів: напишіть final, each або номери многокутників від 1 через кому (1,3)
gradescope-missing = немає файлу з цією відповіддю: здайте { $file }
gradescope-score-rule = оцінка: частка правильних ({ $right }) серед { $changed } клітинок, які сцена змінює, мінус така сама частка за кожну з { $stray } клітинок, записаних там, де буфер зберігає початкове значення; клітинки без відповіді не враховуються
gradescope-ambiguous = на це відповідають одразу { $files }: жоден не оцінено; здайте один
gradescope-unused = не оцінено (завдання їх не вимагає): { $files }
usage-same-student-twice = { $path }: { $files } — обидва «{ $student }», коли імена показано: перейменуйте один; нічого не оцінено
usage-gradebook-cannot-tell = «{ $first }» і «{ $second }» для журналу оцінок — один студент (та сама клітинка без урахування регістру): перейменуйте один; нічого не записано
png-figure-too-many-pixels = за такого --scale PNG мав би понад { $max } пікселів: вкажіть менше
check-more-cells = … і ще { $count } { $count ->
    [one] клітинка відрізняється
    [few] клітинки відрізняються
   *[other] клітинок відрізняються
}, не перелічено

grade-skipped = не перевірено: { $file } — не файл відповіді (ІМ'Я.frame.txt або ІМ'Я.depth.txt)
grade-skipped-near = не перевірено: { $file } схожий на { $buffer } учня { $student }: назвіть його { $name }

## The browser playground
play-title = Пісочниця zsim: z-буфер крок за кроком
play-intro = Змінюйте сцену; усі буфери нижче малює бібліотека zsim, скомпільована для вашого браузера.
play-language = Мова
play-scene = Сцена
play-width = ширина
play-height = висота
play-frame-bits = бітів буфера кадру
play-depth-bits = бітів z-буфера
play-depth-test = тест глибини
play-preset = правила
play-preset-none = як у книзі
play-snap = крок сітки
play-polygon = многокутник
play-value = значення
play-add-polygon = + многокутник
play-remove-polygon = − многокутник
play-add-vertex = + вершина
play-remove-vertex = − вершина
play-json = JSON сцени
play-share = Посилання на цю сцену
play-shared = Посилання — в адресному рядку: скопіюйте його звідти.
play-buffers = Буфери після кожного многокутника
play-final = Підсумкові буфери (як їх друкує zsim run --final)
play-grid = Растр
play-grid-help = Перетягніть вершину, щоб зсунути її; клацніть піксель, щоб побачити його історію.
play-explain = Історія пікселя
play-stepper = Рядок за рядком
play-figure = Рисунок
play-homework = Перевірити домашнє завдання
play-homework-help = Введіть або вставте матрицю так, як її друкує книга, починаючи з верхнього рядка.
play-check = Перевірити
play-answer-grid = Ввести в сітку (починаючи з очищеного буфера)
play-after = після
play-your-answer = ваша відповідь
play-too-large = Сцена завелика, щоб показати її по клітинках (понад { $cells } пікселів або { $polygons } многокутників): показано лише підсумкові буфери.
play-not-printed = У цьому растрі понад { $cells } пікселів: буфери намальовано, але тут не надруковано; їх друкує zsim run --final.
play-no-antialias = Ця сторінка малює сцену без згладжування; згладжені зображення показує zsim run.
play-no-polygon = Такого многокутника в сцені немає.
play-not-json = Сцена — не JSON: { $reason }
play-bad-edit = Ця зміна не пасує до JSON цієї сцени.
play-bad-address = В адресі немає сцени: після #scene= має йти JSON сцени в base64url.

## The lesson (teach::lesson): the same in every front end.
lesson-key-next = наступний рядок
lesson-key-back = назад
lesson-key-next-polygon = наступний багатокутник
lesson-key-previous-polygon = попередній багатокутник
lesson-key-skip = пропустити питання цього рядка
lesson-key-quit = вихід
lesson-keys = клавіші: { $keys }, g Y перейти до рядка Y; відповідь перевіряється за Enter
lesson-hint-misconception = схоже, що { $what }
lesson-hint-is-written = цей піксель проходить тест глибини: порівняйте його точне z зі збереженим значенням ще раз
lesson-hint-is-not-written = цей піксель не проходить тест глибини: порівняйте його точне z зі збереженим значенням ще раз
lesson-hint-centre-on-boundary = центр лежить точно на межі багатокутника: яке правило його вирішує?
lesson-hint-column-outside = ви взяли стовпець, центр якого лежить поза відрізком
lesson-hint-column-left-out = ви пропустили стовпець, центр якого лежить усередині відрізка
lesson-hint-other = обчисліть z у центрі пікселя за площиною, порівняйте зі збереженим значенням, потім округліть
lesson-right = { $said }: правильно. { $why }
lesson-right-second = { $said }: правильно з другої спроби. { $why }
lesson-try-again = { $said }: ще ні: { $hint } (ще одна спроба)
lesson-revealed = { $said }: знову неправильно. Відповідь: { $expected }: { $why }
lesson-skipped = пропущено питань: { $count } (вважаються без відповіді)
lesson-score = опитування: з першої спроби { $first }, з другої { $second }, показано { $revealed }, пропущено { $skipped }, усього питань { $asked }
lesson-ask-coverage = { $polygon }, рядок { $scanline }: центри яких стовпців він покриває? (стовпці як перший-останній, наприклад 3-7, або - якщо жодних)
lesson-ask-depth = піксель ({ $x }, { $y }), збережено { $stored }: що в z-буфері після? (значення, або - якщо не записаний)
lesson-ask-frame = піксель ({ $x }, { $y }), у буфері кадру { $before }: що в буфері кадру після? (значення, або - якщо не записаний)
lesson-last-try = остання спроба: { $ask }
lesson-questions-open = на цьому рядку відкритих питань: { $open }; спершу дайте відповідь або натисніть s, щоб пропустити
lesson-no-such-polygon = багатокутника { $polygon } немає: у сцені їх { $count }
page-no-quiz = Ця сторінка показує кроки й нічого не питає: опитування є в браузерній пісочниці (цю сторінку команда пише, коли zsim зібрано з нею; див. розділ посібника «Браузерна пісочниця») і в zsim step --quiz.
play-scene-name = сцена
page-skip = Пропустити (s)
play-quiz-kind = про що питає опитування
play-coverage-kind = покриті стовпці, потім z-буфер
play-examples = Приклади
play-reset = Скинути
play-copied = Посилання скопійовано.
play-grid-label = Растр: стрілки рухають курсор пікселя, Enter пояснює цей піксель
play-buffer-kind = який буфер
play-example-rogers = Приклад із книги
play-example-section = Переріз із книги
play-example-less = Тест глибини «менше»
play-example-cull = Відсікання задніх граней
play-example-concave = Неопуклий багатокутник
play-legend = Значення буфера кадру:
play-hidden = ще покритих пікселів: { $count }, питаються по одному
play-legend-value = { $value }
lesson-said-meant = { $said } ({ $meant })
play-error-line = рядок { $line }: { $text }
answer-empty = файл порожній: у ньому немає жодного рядка відповіді
answer-decimal-comma = рядок { $line }: у { $text } десяткова кома; кожна клітинка — ціле число (клітинки розділяються пробілами)
usage-answer-without-buffer = { $path } — це відповідь: вкажіть її як --frame { $path } або --depth { $path }
grade-mistakes-more = ще клітинок, у яких помилилися двоє або більше студентів, не показано: { $count }
check-hint-other-buffer = це точно { $other }, а не { $buffer }: чи не здано його як інший буфер?
play-scene-too-long = У цій сцені { $bytes } байт; сторінка читає сцени до { $max } байт: її намалює zsim run.
lesson-nothing-to-skip = тут немає відкритих питань: пропускати нічого
