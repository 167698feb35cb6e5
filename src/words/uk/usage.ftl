# zsim's words in Ukrainian: requests that do not fit the command or the scene.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

usage-arith-plain-rules = арифметика { $arith } моделює простий алгоритм за правилами підручника; ця сцена потребує інших правил або попіксельних ефектів, які малює точна арифметика
usage-arith-greater-or-less = арифметика { $arith } моделює тести глибини greater і less; ця сцена потребує { $test }, який малює точна арифметика
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
usage-not-a-hard-case = «{ $name }» — не складний випадок: { $names }
usage-exercise-size = вправа має від 4 до 64 пікселів на сторону, а не { $width }×{ $height }
usage-exercise-polygons = у вправі від 1 до 8 багатокутників, а не { $count }
usage-exercise-bits = у вправі вручну буфер кадру має від 1 до 8 бітів, а z-буфер від 1 до 16
usage-exercise-two-polygons = для hidden та intersecting потрібні два багатокутники або більше
usage-exercise-not-found = за { $tries } спроб не знайшлося сцени з { $polygons } багатокутників на растрі { $width }×{ $height } з усіма випадками { $cases }; попросіть менше випадків, більше багатокутників або більший растр
usage-inside-needs-pixel-order = --inside вибирає тест «точка в багатокутнику» для --order pixels; додайте --order pixels
usage-tiles-need-format-none = --tile і --threads стосуються --format none, --final і --after (інакше показується стан після кожного багатокутника, намальованого по черзі)
usage-format-none-is-plain = --format none підсумовує цикл z-буфера; із --segments, --order pixels або згладжуванням використовуйте text або json
usage-no-scanlines = { $polygon } не має рядків сканування: { $why }
usage-scanline-rows = { $reach }: його рядки { $first } … { $last }
usage-scanline-no-rows = { $reach }: він не сягає жодного рядка растра
usage-output-is-input = { $path } — один із входів, які читає zsim: запишіть вивід в інше місце
usage-output-would-replace = у { $path } вже є { $files }{ $more ->
    [0] {""}
   *[other] { " " }і ще { $more }
}: zsim не замінює файли; виберіть нову або порожню теку
usage-tile-zero = --tile приймає 1 піксель і більше (з 0 нічого не малюється)
usage-compare-gpu-plain = з GPU порівнюється простий алгоритм: ця сцена потребує попіксельних ефектів або згладжування
usage-pixel-not-xy = «{ $text }» — не X,Y (наприклад, 20,15)
usage-pixel-coordinate = «{ $text }» — не координата пікселя
usage-arith = «{ $text }» — не режим арифметики: `exact`, `f64`, `f64-incremental`, `f32-incremental`, `f32`, `f32-edge` або `fixed:K` (K від 0 до 24)
usage-missing = бракує: { $args }
usage-invalid-value = «{ $value }» не підходить для { $arg }: { $reason }
usage-unknown-argument = невідомий параметр { $arg }
usage-unknown-command = невідома команда { $name }
usage-conflict = { $arg } не можна задавати разом із { $other }
usage-see-help = довідка: zsim --help
usage-no-submission = { $folder }: тут немає відповіді: frame.txt, depth.txt, after-N.frame.txt або after-N.depth.txt
usage-identity-column = --identity: ця платформа не імпортує за стовпцем «{ $column }» (Moodle: email, idnumber, username; Canvas: id, sis-user-id, sis-login-id)
usage-no-points = --points має бути не менше 1
usage-tinyrenderer-size = «{ $text }» — не сторона зображення: { $min } … { $max } пікселів
usage-not-a-preset = «{ $text }» — не набір правил: використовуйте rogers, buet, gl, vulkan (d3d, webgpu) або tinyrenderer
segments-form = «{ $text }» — не strips:N, tiles:N і не rows:1 (N ≥ 1)
segments-count = «{ $count }» — не ціле число
segments-rows = rows приймає лише 1 (по одному рядку розгортки)
usage-output-name-too-long = { $path }: ім'я довше, ніж допускають файлові системи ({ $max } байтів); нічого не записано
usage-output-twice = { $path } було б записано однією командою двічі; нічого не записано
usage-same-answer-twice = { $path }: { $files } відповідають за той самий буфер того самого стану: здайте один
grade-left-out-of-import = не ввійшли до журналу оцінок: «{ $first }» і «{ $second }» для журналу — один студент (та сама клітинка без урахування регістру): перейменуйте один та імпортуйте їхні рядки знову
usage-answer-without-buffer = { $path } — це відповідь: вкажіть її як --frame { $path } або --depth { $path }
usage-line-too-long = рядок довший за { $max } байтів: урок закінчується тут, його підсумок вище
usage-html-quiz = --html --quiz записує пісочницю, вікторина якої рахує точно: приберіть --arith
usage-no-playground = цей zsim зібрано без браузерної пісочниці: встановіть пакет Debian або архів випуску, у яких вона є, або зберіть zsim з нею (web/build, потім ZSIM_PLAYGROUND=target/web cargo build)
