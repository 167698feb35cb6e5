# zsim's words in Ukrainian: drawing a scene: run's reports, the stages, headings, rules and presets, effects, explain, figures, the GPU and speed.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
depth-test-greater = більше
depth-test-less = менше
depth-test-greater-equal = більше або дорівнює
depth-test-less-equal = менше або дорівнює
depth-test-always = завжди
depth-test-never = ніколи
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
heading-polygon-scanline = { " " }{ $polygon }, рядок сканування { $scanline }
heading-end-of-scene = { " кінець сцени" }
end-of-scene = кінець сцени
span-line = відрізок { $n }: { $left } … { $right }; { $columns }
span-no-centre = жодного центру
test-passes-uncompared = { $test } пропускає,{ " " }
test-not = { "не " }
outcome-hidden-short = прихований
depth-steps-from = { ", " }кроків −a/c від { $start }: { $count }
meant-not-written = не записується
meant-value-written = записане значення
meant-value-kept = не записується: значення, що залишається
meant-value = значення
frame-after-scanline = буфер кадру після цього рядка
depth-after-scanline = z-буфер після цього рядка
scanline-of-count = рядок { $at } з { $count }
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
fate-outside-view = він поза видимим об'ємом (−w ≤ x, y, z ≤ w): відсікається повністю й не малюється
heading-outside-view = { $start }: поза видимим об'ємом (−w ≤ x, y, z ≤ w): відсікається повністю, не малюється
heading-view = { "; простір відсікання: " }усередині видимого об'єму { $inside } з { $of } вершин, після відсікання, ділення на w та області виведення малюється як { $n }-кутник
polygon-opacity = непрозорість { $alpha } поза діапазоном 0 … 1
polygon-value-too-wide = значення { $value } не вміщується в { $bits }-бітний буфер кадру (не більше за { $max })
list-or = { $rest } або { $last }
rules-describe = правила { $preset }: { $rows }; { $columns }; { $store }
rules-rows-half-open = рядки напіввідкриті (min ≤ y < max), перетини попарно
rules-rows-closed = рядки замкнені (min ≤ y ≤ max), один відрізок від найменшого до найбільшого перетину
rules-rows-top-left = рядки «згори-зліва» (min < y ≤ max: центри на верхньому ребрі входять, на нижньому ні), перетини попарно
rules-columns-centre-inside = стовпці, чий центр лежить у відрізку
rules-columns-cell-holds = стовпці від комірки з x_a до комірки з x_b
rules-columns-half-open = стовпці, чий центр лежить у [x_l, x_r): центри на лівому ребрі входять, на правому ні
rules-store-quantized = глибина округлюється вгору на половині й насичується
rules-store-exact = глибина зберігається точно
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
run-summary = { $path }: багатокутників { $polygons }, перевірено центрів пікселів: { $tested }, записано: { $written }; ефекти: { $effects }; стадії: { $stages }; читання { $read } мс{ $made }, растеризація { $raster } мс, потоків: { $threads } ({ $rate } млн пікселів/с); пам'ять: буфери { $buffers }, сцена { $scene }{ $peak }
run-summary-peak = , пік резидентної пам'яті { $peak }
run-summary-peak-ratio = , пік резидентної пам'яті { $peak } ({ $ratio }× буфери + сцена)
run-summary-made = , створення буферів { $made } мс
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
speed-fresh = увесь прогін zsim зі створенням нових буферів (як створення буферів і растеризація `zsim run` разом): { $fresh } мс (медіана), { $ratio }× часу GPU
speed-memory = zsim перевіряв { $rate } млн центрів пікселів за секунду; копія { $megabytes } МБ буферів зайняла { $copy } мс ({ $bandwidth } ГБ/с), що при { $bytes } байтах на піксель, прочитаних і записаних по разу, дозволяє { $limit } млн пікселів за секунду
gpu-why-depth-unread = GPU показує { $shown }; за правилами сцени лишається { $book } (вирішили глибини: GPU інтерполює їх у f32)
gpu-no-vulkan = пристрій Vulkan не знайдено: { $reason } (установіть mesa-vulkan-drivers)
gpu-not-built = цей zsim зібрано без можливості { $feature }: зберіть його командою `cargo install --path . --features { $feature }`
figures-not-built = цей zsim зібрано без рисунків { $format } (можливість figures, вимкнена у звичайній збірці): зберіть його командою `cargo install --path . --features figures`; у пакеті Debian вони є. Рисункам SVG і TeX нічого не потрібно
rules-store-truncated = глибина відкидається до цілого (округлюється вниз) з насиченням
rules-sample-corner = ; вибірка в цілих точках (x, y), кутах пікселів
rules-compare-level = ; порівнюється глибина, округлена так само, як записується
rules-min-area = ; багатокутники з орієнтованою площею меншою за { $area } пропускаються
stage-store-truncated = запис (відкидання дробової частини, насичення до 0…{ $max })
preset-tinyrenderer = урок tinyrenderer про z-буфер
fate-small-area = його орієнтована площа менша за межу правил (зворотна грань або скалка): його пропущено
heading-small-area = { $start }: площина { $plane }, пропущено (орієнтована площа менша за межу правил: зворотна грань або скалка)
explain-others = ще { $count } багатокутників не доходять до рядка сканування цього пікселя: { $skipped } не малюються взагалі (пропущені, відсічені або видимі з ребра), у { $off } рядки лежать деінде
explain-corner-sample = за правилами вибірку беруть у цілій точці ({ $x }, { $y }): zsim малює сцену, зсунуту на ½, щоб цей центр був цією точкою, і координати нижче — зсунуті
stored-truncated = в z-буфер записується { $stored } ({ $value } без дробової частини — { $stored })
stored-truncated-saturated = в z-буфер записується { $stored } ({ $value } без дробової частини, з насиченням до { $stored })
heading-scene = Сцена
heading-scene-json = JSON сцени
heading-buffers-each-polygon = Буфери після кожного многокутника
heading-final-buffers = Підсумкові буфери (як їх друкує zsim run --final)
heading-raster = Растр
heading-pixel-history = Історія пікселя
heading-scanline-by-scanline = Рядок за рядком
heading-figure = Рисунок
heading-homework = Перевірити домашнє завдання
antialias-not-drawn = Ця сторінка малює сцену без згладжування; згладжені зображення показує zsim run.
heading-examples = Приклади
buffer-kind-label = який буфер
pixels-hidden-asked = ще покритих пікселів: { $count }, питаються по одному
