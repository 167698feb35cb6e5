# zsim's words in Ukrainian: reading a scene: its JSON, settings, numbers, geometry; files and what the system says.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

subject-it = він
scene-header = сцена { $path }: { $width }×{ $height } пікселів, буфер кадру { $frame_bits } біт, z-буфер { $depth_bits } біт (0…{ $depth_max }), тест глибини { $test } ({ $rule }), після очищення { $clear }
scene-stages = етапи: { $stages }
scene-effects = ефекти: { $effects }
file-written-about = записано { $path } ({ $about })
file-written-page = записано { $path } (відкрийте його в браузері; мережа не потрібна)
scene-covers-no-pixel = Ця сцена не покриває жодного пікселя.
error-read = { $path }: не вдається прочитати: { $reason }
error-write = { $path }: не вдається записати: { $reason }
error-polygon = { $path }: { $polygon }: { $problem }
geometry-too-few = вершин { $count }; багатокутник мусить мати щонайменше 3
geometry-too-many = вершин { $count }; zsim приймає щонайбільше { $max }
geometry-out-of-range = у вершини { $vertex } координата { $value } поза точним діапазоном: за спільного знаменника багатокутника { $denominator } |координата| × 2 × { $denominator } має бути не більшою за 2^4096 (візьміть менші координати або менше знаків після коми)
digits = { $count } цифр
geometry-off-plane-z = не плоский: вершина { $vertex } відстоїть від площини { $plane }, проведеної через вершини { $i }, { $j }, { $k }, на Δz = { $off }
geometry-off-plane = не плоский: вершина { $vertex } дає { $off } замість 0 у рівнянні площини { $plane }, проведеної через вершини { $i }, { $j }, { $k }
vertex-decimal-comma = у вершині чотири числа, { $written }, серед вершин [x, y, z]: { $comma } — це десяткова кома? У JSON дробову частину відділяє крапка: напишіть { $meant }
clip-space-mixed = змішує вершини [x, y, z] з вершинами [x, y, z, w] у просторі відсікання: запишіть усі вершини багатокутника однаково
clip-space-alone = заданий вершинами [x, y, z, w] у просторі відсікання, які переносить на растр перетворення області виведення; вони не поєднуються з вікном і з ефектом перспективи
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
origin-supersampled = сцена із суперсемплінгом { $factor }×
origin-snapped = сцена, прив'язана до fixed:{ $bits }
png-not-an-image = не зображення PNG ({ $reason })
png-too-large = PNG завеликий
png-broken = пошкоджене зображення PNG ({ $reason })
png-colour-type = неочікуваний колірний тип PNG { $kind }
place-vertex-on-scanline = багатокутник { $polygon }: вершина { $vertex } ({ $x }; { $y }) лежить на рядку сканування ряду { $row }
place-centre-on-edge = піксель ({ $x }, { $y }): його центр лежить на ребрі багатокутника { $polygon }
place-spans = багатокутник { $polygon }: у ряду { $row } відрізків: { $spans }
place-half-depth = піксель ({ $x }, { $y }), багатокутник { $polygon }: z = { $z } округлюється вгору до { $stored }
place-saturation = піксель ({ $x }, { $y }), багатокутник { $polygon }: z = { $z } округлюється до { $rounded }, зберігається { $stored }
place-hidden = піксель ({ $x }, { $y }), багатокутник { $polygon }: z = { $z } не проходить тест проти збереженого { $stored }
place-intersecting = багатокутники { $first } і { $second }: кожен десь перед іншим
file-written = записано { $path }
file-written-in = записано { $files } у { $path }
png-no-fonts = у цій системі немає шрифтів, і текст зник би; запишіть SVG (-o FILE.svg)
png-figure-too-large = рисунок завеликий
error-output = не вдається записати вивід: { $reason }
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
stdout-closed = стандартний вивід закрито
token-cut = { $shown }… ({ $count } символів)
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
error-outside-folder = { $path }: ім'я всередині файлу має лишатися в теці цього файлу ({ $folder }): без «..» і без абсолютного шляху
png-declares-too-many-pixels = PNG оголошує { $width } × { $height } пікселів, більше, ніж декодує zsim ({ $max })
png-figure-too-many-pixels = за такого --scale PNG мав би понад { $max } пікселів: вкажіть менше
limit-cells-or-polygons = Сцена завелика, щоб показати її по клітинках (понад { $cells } пікселів або { $polygons } многокутників): показано лише підсумкові буфери.
limit-printed-cells = У цьому растрі понад { $cells } пікселів: буфери намальовано, але тут не надруковано; їх друкує zsim run --final.
limit-figure-cells = Сторінка малює рисунки растрів до { $cells } пікселів; цей намалює zsim figure.
scene-not-json = Сцена — не JSON: { $reason }
edit-does-not-fit = Ця зміна не пасує до JSON цієї сцени.
address-holds-no-scene = В адресі немає сцени: після #scene= має йти JSON сцени в base64url.
scene-name-default = сцена
error-at-line = рядок { $line }: { $text }
limit-scene-bytes = сторінка читає сцени до { $max } байт; у цій { $bytes }: її малює zsim run
limit-page-cells = сторінка малює растри до { $max } пікселів; у цьому { $cells }: його малює zsim run
limit-page-polygons = сторінка малює до { $max } багатокутників; у цій сцені { $count }: її малює zsim run
limit-page-vertices = сторінка малює багатокутники до { $max } вершин; у багатокутника { $polygon } їх { $count }: сцену малює zsim run
limit-page-reach = сторінка малює сцени, багатокутники яких разом займають до { $max } пікселів (обмежувальний прямокутник кожного на растрі); у цій { $reach }: її малює zsim run
limit-recorded-reach = записана сторінка проходить сцени, багатокутники яких разом займають до { $max } пікселів растра (за обмежувальним прямокутником кожного); у цій { $reach }: її проходить zsim step у терміналі
limit-recorded-page = записана сторінка проходить сцени до { $cells } пікселів і { $polygons } багатокутників; у цій { $has_cells } пікселів і { $has_polygons } { $has_polygons ->
    [one] багатокутник
    [few] багатокутники
   *[many] багатокутників
}: її проходить zsim step у терміналі
