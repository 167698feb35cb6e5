# Класс: списки студентов, манифест, варианты, раздаточные материалы, проверка по ключу каждого студента, автопроверка на платформах.
roster-empty = { $path }: в списке нет ни одного студента
roster-unknown-header = { $path }: строка 1: zsim не знает такого списка: его столбцы { $headers }; дайте выгрузку Moodle, Canvas, Gradescope или PrairieLearn либо по одному идентификатору в строке
roster-no-such-column = { $path }: нет столбца «{ $column }», по которому называть студентов; столбцы списка: { $headers }
roster-empty-identity = { $path }: строка { $line }: у студента пусто в столбце { $column }
roster-duplicate = { $path }: строка { $line }: { $identity } уже есть в списке (строка { $first }); журналы оценок сравнивают идентификаторы без учёта регистра
roster-unnameable = { $path }: строка { $line }: «{ $identity }» не может быть именем файлов студента (без /, \, :, *, ?, ", <, >, | и управляющих символов, не с точки, не длиннее 200 байт): выберите другой столбец через --identity
roster-too-many = { $path }: больше { $max } студентов: разделите класс
roster-unreadable = { $path }: строка { $line }: { $reason }
manifest-layout = { $place }: это не variants.json класса: { $why }
manifest-format = { $place }: «{ $found }» — не формат, который читает этот zsim (он читает «{ $expected }»)
manifest-hand-in = { $place }: студент сдаёт «frame», «depth» или оба
manifest-twice = { $place }: { $what } встречается в манифесте дважды
manifest-unnameable = { $place }: «{ $identity }» не может быть именем файлов студента
manifest-scene = { $place }: { $why }
class-student-unfit = нет варианта для { $identity }: { $why }
class-reseed-not-on-roster = --reseed { $identity }: в списке нет студента с таким идентификатором
class-counts = --times принимает 1 … 8, --distinct 1 … 1024
class-not-a-rule = «{ $name }» — не ошибочное правило: { $names }
class-hand-in-list = --hand-in «{ $name }»: укажите frame, depth или оба через запятую
class-worksheet-title = { $name } · вариант { $code }: растр { $width }×{ $height }, { $count ->
    [one] { $count } многоугольник
    [few] { $count } многоугольника
   *[many] { $count } многоугольников
  }
class-worksheet-hand-in = Сдайте { $files }, сохранив их первые строки (вариант { $code }).
class-worksheets-title = { $count ->
    [one] { $count } лист задания
    [few] { $count } листа задания
   *[many] { $count } листов задания
  }
class-template-what = { $buffer } после последнего многоугольника, { $name }
class-template-how = сначала верхняя строка, по строке растра в строке файла, { $width } чисел через пробел; ? для ячейки, которую вы не вычислили
class-hand-in-who = { $name } ({ $identity }), вариант { $code }
class-hand-in-files = Сдайте { $count ->
    [one] один файл
    [few] { $count } файла
   *[many] { $count } файлов
  }:
class-hand-in-file = { $file }: { $buffer } после последнего многоугольника
class-hand-in-format = Каждый: { $height } строк по { $width } целых чисел, сначала верхняя строка, через пробел; ? для ячейки, которую вы не вычислили. Начните с пустых файлов рядом с этим и сохраните их первые строки (вариант { $code }).
class-hand-in-link = Попробуйте в браузере, с вопросами: { $link }
class-summary = { $students ->
    [one] { $students } студент
    [few] { $students } студента
   *[many] { $students } студентов
  }, начальное число курса { $seed }: у каждого свой вариант { $width }×{ $height } с { $polygons } многоугольниками; в каждом { $hard } ровно { $times ->
    [one] { $times } раз
    [few] { $times } раза
   *[many] { $times } раз
  } и никаких других трудных случаев, а каждое ошибочное правило ({ $rules }) отличается от ключа не менее чем в { $distinct } ячейках
class-column-code = вариант
class-column-apart = правила отличаются (меньше всего ячеек)
course-misnamed = { $file } назван неправильно и не проверен: назовите его { $expected }
course-swapped = в { $file } стоит вариант { $code }, а это вариант студента { $owner }: листы перепутаны?
course-two-files = { $buffer } дают два файла: { $files }; ни один не проверен
course-not-on-roster = { $file } не проверен: в списке нет { $identity }
course-grade-summary = класс { $class } по { $variants }: { $students ->
    [one] { $students } студент
    [few] { $students } студента
   *[many] { $students } студентов
  }; верно: { $ok }, с ошибками: { $wrong }, с негодными файлами: { $malformed }, без ответа: { $missing }
course-by-kind = ошибки по видам трудных случаев (ошиблись там из тех, в чьей сцене он есть):
course-kind-line = { $case }: { $wrong } из { $holding }, { $cells ->
    [one] { $cells } ячейка
    [few] { $cells } ячейки
   *[many] { $cells } ячеек
  }
course-changes = баллы, изменившиеся с прошлой проверки: { $count }
course-change = { $student }: { $before } → { $after }: { $why }
course-change-added = раньше не проверялся
course-change-removed = больше нет в манифесте
course-change-scene = его сцену изменили в манифесте
course-change-files = его файлы изменились
course-change-key = ключ той же сцены изменился (другой zsim)
course-change-rule = те же файлы и ключ, оценены по другому правилу
course-feedback = { $student } (вариант { $code }): баллы { $score } %, { $status }
platform-unreadable = { $file }: { $why }
platform-unknown-student = эту работу сдал никто из списка класса: платформа назвала { $given }; попросите преподавателя добавить вас
platform-group = группа студентов с разными вариантами ({ $students }): каждый сдаёт свою работу
platform-unknown-code = варианта { $code } нет в манифесте класса: обратитесь к преподавателю
platform-needs-file = не дан файл платформы, называющий работу (--metadata для Gradescope, --data для PrairieLearn)
platform-question-title = Z-буфер вручную
platform-question-variant = Ваш вариант:
usage-grade-variants-folder = grade --variants FILE принимает одну папку — папку класса: zsim grade --variants DIR/variants.json CLASS
usage-grade-scene-and-class = grade принимает сцену и папку класса: zsim grade SCENE CLASS (или --variants DIR/variants.json CLASS)
class-page-save = Сохранить как файл для сдачи
class-page-variant = Ваш вариант: { $code } ({ $student })
class-page-score = баллы { $score } %
