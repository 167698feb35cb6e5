# zsim's words in Ukrainian: stepping and the lesson: the stepper's views and keys, the questions, hints and misconceptions, the page's controls.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
title-stepper = zsim step ·{ $heading } · { $view }{ $score } · ? клавіші
score-short = { " · опитування " }{ $right }/{ $asked }
key-does-nothing = ця клавіша тут нічого не робить: ? покаже клавіші
no-later-polygon = жоден наступний багатокутник не покриває пікселів
no-earlier-polygon = жоден попередній багатокутник не покриває пікселів
go-to-row-prompt = перейти до рядка сканування ряду: { $text }▏ (Enter — перейти, Esc — скасувати)
keys-summary = n/→ далі · b/← назад · p/P багатокутник · g перейти · f/z буфер · m по пікселях · q вихід
no-scanline = немає рядка сканування
columns-shown = x { $first } … { $last } з 0 … { $max }
pixel-table-heading = x { $z } тест → у z-буфер (кадр)
keys-pixel-by-pixel = m: по пікселях, з поясненнями
pixel-centre-depth = ({ $x }, { $y }): центр x = { $centre }, z = { $z }{ $steps }
keys-heading = { " клавіші " }
keys-help =
    g                  перейти до рядка сканування ряду
    f / z              показати буфер кадру / z-буфер
    m                  по пікселях / по рядках
    PgUp PgDn < >      прокрутити растр
    { "[ ]" }                прокрутити таблицю
    ?                  ці клавіші (будь-яка клавіша закриває)

    жовтим: покриті пікселі відрізка
    блакитним: попередні записи цього багатокутника
quiz-mistakes = ваші помилки:
quiz-coverage-hint = введіть покриті стовпці як перший-останній (кілька відрізків через пробіл: 3-5 9-12) або -, якщо жодного
quiz-coverage-why = відрізки: { $spans }; стовпець покритий, якщо його центр x + 1/2 лежить в одному з них
quiz-coverage-mistake = рядок { $row } { $polygon }: ваша відповідь — стовпці { $said }, правильно { $right }: { $why }
quiz-depth-hint = введіть значення, яке буде в z-буфері, або - якщо не записується (q завершує опитування)
quiz-not-an-answer = «{ $text }» — не відповідь: { $hint }
quiz-does-not-fit = { $text } не вміщується в цей z-буфер: його комірки зберігають цілі рівні 0 … { $max }; введіть знову
quiz-keeps = - (залишається { $value })
quiz-depth-mistake = ({ $x }, { $y }) { $polygon }: ваша відповідь { $said }, правильно { $right }: { $reason }
command-back = ◀ Назад (b)
command-next = Далі ▶ (n)
command-previous-polygon = ◀◀ Багатокутник (P)
command-next-polygon = Багатокутник ▶▶ (p)
command-show-frame = Буфер кадру (f)
command-show-depth = Z-буфер (z)
quiz-label = опитування
column-stored = було
column-depth-after = z-буфер після
column-why = чому
keeps-value = – (залишається { $value })
command-check-answers = Перевірити відповіді
step-skip-fate = { $polygon }: { $why }
step-skip-no-scanline = { $polygon }: не сягає жодного рядка сканування растра
step-skip-no-centre = { $polygon }, рядок сканування { $scanline }: не покрито жодного центру пікселя
step-skip-no-centre-no-crossings = { $polygon }, рядок сканування { $scanline }: не покрито жодного центру пікселя (перетинів немає)
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
pixel-order-ray = трасування променя (правило вершин «ліворуч відкрито, праворуч замкнено»; межа рахується)
pixel-order-arc = метод довжини дуги (таблиця квадрантів; межа рахується)
pixel-order-heading = порядок: для кожного пікселя, для кожного багатокутника, одна змінна глибини (китайський конспект); тест належності: { $test }
pixel-order-header-polygon = багатокутник
pixel-order-header-why = чому тести належності розходяться
pixel-order-on-boundary = центр лежить точно на межі: дуга вважає його внутрішнім, а правило півінтервалу не включає верхні ребра й вершини (ребро рахується лише біля нижнього кінця)
pixel-order-winding = багатокутник обходить центр { $winding } разів: дуга вважає ненульову кількість обертів внутрішньою, парні перетини (парність) — зовнішньою
pixel-order-disagree = центрів, де дуга й правило рядків сканування розходяться: { $count }
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
quiz-frame-hint = введіть значення, яке буде в буфері кадру, або - якщо не записується (q завершує опитування)
quiz-frame-does-not-fit = { $text } не вміщується в цей буфер кадру: його комірки зберігають цілі значення 0 … { $max }; введіть знову
title-scene-editor = Пісочниця zsim: z-буфер крок за кроком
intro-scene-editor = Змінюйте сцену; усі буфери нижче малює бібліотека zsim, скомпільована для вашого браузера.
field-language = Мова
field-width = ширина
field-height = висота
field-frame-bits = бітів буфера кадру
field-depth-bits = бітів z-буфера
field-depth-test = тест глибини
field-preset = правила
field-preset-none = як у книзі
field-snap = крок сітки
field-polygon = многокутник
field-value = значення
command-add-polygon = + многокутник
command-remove-polygon = − многокутник
command-add-vertex = + вершина
command-remove-vertex = − вершина
command-copy-link = Посилання на цю сцену
link-in-address-bar = Посилання — в адресному рядку: скопіюйте його звідти.
raster-help = Перетягніть вершину, щоб зсунути її; клацніть піксель, щоб побачити його історію.
homework-help = Введіть або вставте матрицю так, як її друкує книга, починаючи з верхнього рядка.
command-check = Перевірити
column-after = після
column-your-answer = ваша відповідь
no-such-polygon = Такого многокутника в сцені немає.
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
lesson-right = { $said }: правильно. { $why }
lesson-right-second = { $said }: правильно з другої спроби. { $why }
lesson-try-again = { $said }: ще ні: { $hint } (ще одна спроба)
lesson-hint-neighbouring-row = це стовпці сусіднього рядка, нижче чи вище: цей рядок розгортки — y = рядок + ½
lesson-hint-rounded-up = схоже, ви округлили вгору: z-буфер зберігає найближче ціле (половини вгору)
lesson-hint-half-down = схоже, ви округлили половину вниз: половини округлюються вгору
lesson-try-again-plain = { $said }: ще ні (ще одна спроба)
lesson-revealed = { $said }: знову неправильно. Відповідь: { $expected }: { $why }
lesson-skipped = пропущено питань: { $count } (вважаються без відповіді)
lesson-score = опитування: з першої спроби { $first }, з другої { $second }, показано { $revealed }, пропущено { $skipped }, усього питань { $asked }
lesson-ask-coverage = { $polygon }, рядок { $scanline }: центри яких стовпців він покриває? (стовпці як перший-останній, наприклад 3-7, або - якщо жодних)
lesson-ask-depth = піксель ({ $x }, { $y }), збережено { $stored }: що в z-буфері після? (значення, або - якщо не записаний)
lesson-ask-frame = піксель ({ $x }, { $y }), у буфері кадру { $before }: що в буфері кадру після? (значення, або - якщо не записаний)
lesson-last-try = остання спроба: { $ask }
lesson-questions-open = на цьому рядку відкритих питань: { $open }; спершу дайте відповідь або натисніть s, щоб пропустити
lesson-no-such-polygon = багатокутника { $polygon } немає: у сцені їх { $count }
quiz-not-on-recorded-steps = Ця сторінка показує кроки й нічого не питає: опитування є в браузерній пісочниці (цю сторінку команда пише, коли zsim зібрано з нею; див. розділ посібника «Браузерна пісочниця») і в zsim step --quiz.
command-skip = Пропустити (s)
command-end-quiz = Закінчити тест (q)
quiz-kind-label = про що питає опитування
quiz-kind-coverage = покриті стовпці, потім z-буфер
command-reset = Скинути
link-copied = Посилання скопійовано.
raster-label = Растр: стрілки рухають курсор пікселя, Enter пояснює цей піксель
example-rogers = Приклад із книги
example-section = Переріз із книги
example-less = Тест глибини «менше»
example-cull = Відсікання задніх граней
example-concave = Неопуклий багатокутник
legend-heading = Значення буфера кадру:
legend-value = { $value }
lesson-said-meant = { $said } ({ $meant })
lesson-nothing-to-skip = тут немає відкритих питань: пропускати нічого
step-line-not-text = цей рядок — не текст (UTF-8): введіть його знову
lesson-hidden-until-answered = приховано, доки на питання цього рядка не дадуть відповіді або їх не пропустять
