# Клас: списки студентів, маніфест, варіанти, роздаткові матеріали, перевірка за ключем кожного студента, автоперевірка на платформах.
roster-empty = { $path }: у списку немає жодного студента
roster-unknown-header = { $path }: рядок 1: zsim не знає такого списку: його стовпці { $headers }; дайте вивантаження Moodle, Canvas, Gradescope чи PrairieLearn або по одному ідентифікатору в рядку
roster-no-such-column = { $path }: немає стовпця «{ $column }», за яким називати студентів; стовпці списку: { $headers }
roster-empty-identity = { $path }: рядок { $line }: у студента порожньо в стовпці { $column }
roster-duplicate = { $path }: рядок { $line }: { $identity } уже є у списку (рядок { $first }); журнали оцінок порівнюють ідентифікатори без урахування регістру
roster-unnameable = { $path }: рядок { $line }: «{ $identity }» не може бути назвою файлів студента (без /, \, :, *, ?, ", <, >, | і керівних символів, не з крапки, не довше 200 байтів): виберіть інший стовпець через --identity
roster-too-many = { $path }: більше { $max } студентів: розділіть клас
roster-unreadable = { $path }: рядок { $line }: { $reason }
manifest-layout = { $place }: це не variants.json класу: { $why }
manifest-format = { $place }: «{ $found }» — не формат, який читає цей zsim (він читає «{ $expected }»)
manifest-hand-in = { $place }: студент здає «frame», «depth» або обидва
manifest-twice = { $place }: { $what } трапляється в маніфесті двічі
manifest-unnameable = { $place }: «{ $identity }» не може бути назвою файлів студента
manifest-scene = { $place }: { $why }
class-student-unfit = немає варіанта для { $identity }: { $why }
class-reseed-not-on-roster = --reseed { $identity }: у списку немає студента з таким ідентифікатором
class-counts = --times приймає 1 … 8, --distinct 1 … 1024
class-not-a-rule = «{ $name }» — не хибне правило: { $names }
class-hand-in-list = --hand-in «{ $name }»: вкажіть frame, depth або обидва через кому
class-worksheet-title = { $name } · варіант { $code }: растр { $width }×{ $height }, { $count ->
    [one] { $count } багатокутник
    [few] { $count } багатокутники
   *[many] { $count } багатокутників
  }
class-worksheet-hand-in = Здайте { $files }, зберігши їхні перші рядки (варіант { $code }).
class-worksheets-title = { $count ->
    [one] { $count } аркуш завдання
    [few] { $count } аркуші завдання
   *[many] { $count } аркушів завдання
  }
class-template-what = { $buffer } після останнього багатокутника, { $name }
class-template-how = спершу верхній рядок, по рядку растра в рядку файлу, { $width } чисел через пробіл; ? для клітинки, яку ви не обчислили
class-hand-in-who = { $name } ({ $identity }), варіант { $code }
class-hand-in-files = Здайте { $count ->
    [one] один файл
    [few] { $count } файли
   *[many] { $count } файлів
  }:
class-hand-in-file = { $file }: { $buffer } після останнього багатокутника
class-hand-in-format = Кожен: { $height } рядків по { $width } цілих чисел, спершу верхній рядок, через пробіл; ? для клітинки, яку ви не обчислили. Почніть з порожніх файлів поруч із цим і збережіть їхні перші рядки (варіант { $code }).
class-hand-in-link = Спробуйте в браузері, з питаннями: { $link }
class-summary = { $students ->
    [one] { $students } студент
    [few] { $students } студенти
   *[many] { $students } студентів
  }, початкове число курсу { $seed }: у кожного свій варіант { $width }×{ $height } з { $polygons } багатокутниками; у кожному { $hard } рівно { $times ->
    [one] { $times } раз
    [few] { $times } рази
   *[many] { $times } разів
  } і жодних інших складних випадків, а кожне хибне правило ({ $rules }) відрізняється від ключа щонайменше в { $distinct } клітинках
class-column-code = варіант
class-column-apart = правила відрізняються (найменше клітинок)
course-misnamed = { $file } названо неправильно і не перевірено: назвіть його { $expected }
course-swapped = у { $file } стоїть варіант { $code }, а це варіант студента { $owner }: аркуші переплутано?
course-two-files = { $buffer } дають два файли: { $files }; жоден не перевірено
course-not-on-roster = { $file } не перевірено: у списку немає { $identity }
course-grade-summary = клас { $class } за { $variants }: { $students ->
    [one] { $students } студент
    [few] { $students } студенти
   *[many] { $students } студентів
  }; правильно: { $ok }, з помилками: { $wrong }, з непридатними файлами: { $malformed }, без відповіді: { $missing }
course-by-kind = помилки за видами складних випадків (помилилися там з тих, у чиїй сцені він є):
course-kind-line = { $case }: { $wrong } з { $holding }, { $cells ->
    [one] { $cells } клітинка
    [few] { $cells } клітинки
   *[many] { $cells } клітинок
  }
course-changes = бали, що змінилися з попередньої перевірки: { $count }
course-change = { $student }: { $before } → { $after }: { $why }
course-change-added = раніше не перевірявся
course-change-removed = більше немає в маніфесті
course-change-scene = його сцену змінили в маніфесті
course-change-files = його файли змінилися
course-change-key = ключ тієї ж сцени змінився (інший zsim)
course-change-rule = ті самі файли й ключ, оцінені за іншим правилом
course-feedback = { $student } (варіант { $code }): бали { $score } %, { $status }
platform-unreadable = { $file }: { $why }
platform-unknown-student = цю роботу здав ніхто зі списку класу: платформа назвала { $given }; попросіть викладача додати вас
platform-group = група студентів з різними варіантами ({ $students }): кожен здає свою роботу
platform-unknown-code = варіанта { $code } немає в маніфесті класу: зверніться до викладача
platform-needs-file = не дано файл платформи, що називає роботу (--metadata для Gradescope, --data для PrairieLearn)
platform-question-title = Z-буфер вручну
platform-question-variant = Ваш варіант:
usage-grade-variants-folder = grade --variants FILE приймає одну теку — теку класу: zsim grade --variants DIR/variants.json CLASS
usage-grade-scene-and-class = grade приймає сцену й теку класу: zsim grade SCENE CLASS (або --variants DIR/variants.json CLASS)
class-page-save = Зберегти як файл для здачі
class-page-variant = Ваш варіант: { $code } ({ $student })
class-page-score = бали { $score } %
