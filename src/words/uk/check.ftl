# zsim's words in Ukrainian: checking and grading answers, gradebooks, exercises.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
case-line = рядок { $line }: { $problem }
case-unknown-command = невідома команда «{ $command }»
case-keyword-problem = { $keyword }: { $problem }
exercise-notes-settings = вправа: зерно { $seed }, растр { $width }×{ $height }, багатокутників { $polygons }, буфер кадру { $frame_bits } біт, z-буфер { $depth_bits } біт (0 … { $max }), тест глибини { $test }
exercise-notes-asked = замовлено: { $asked } (кандидат { $candidate } з послідовності зерна)
exercise-notes-no-case = жодного особливого випадку
exercise-notes-contains = містить (знайдено в трасі прогону, перше місце кожного):
exercise-notes-none = жодного складного випадку
exercise-notes-next = перевірити відповідь: zsim check { $path } --frame FRAME.txt --depth DEPTH.txt; оцінити групу: zsim grade { $path } CLASS_DIR
diagnosis = імовірна причина: { $what } (пояснює { $explained } з { $wrong } { $wrong ->
    [one] неправильної клітинки
   *[other] неправильних клітинок
})
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
gradescope-test = { $buffer } після { $after }
expect-not-states = «{ $text }» — не список станів: напишіть final, each або номери многокутників від 1 через кому (1,3)
gradescope-missing = немає файлу з цією відповіддю: здайте { $file }
gradescope-score-rule = оцінка: частка правильних ({ $right }) серед { $changed } клітинок, які сцена змінює, мінус така сама частка за кожну з { $stray } клітинок, записаних там, де буфер зберігає початкове значення; клітинки без відповіді не враховуються
gradescope-ambiguous = на це відповідають одразу { $files }: жоден не оцінено; здайте один
gradescope-unused = не оцінено (завдання їх не вимагає): { $files }
check-more-cells = … і ще { $count } { $count ->
    [one] клітинка відрізняється
    [few] клітинки відрізняються
   *[other] клітинок відрізняються
}, не перелічено
grade-skipped = не перевірено: { $file } — не файл відповіді (ІМ'Я.frame.txt або ІМ'Я.depth.txt)
grade-skipped-near = не перевірено: { $file } схожий на { $buffer } учня { $student }: назвіть його { $name }
answer-grid-label = Ввести в сітку (починаючи з очищеного буфера)
answer-empty = файл порожній: у ньому немає жодного рядка відповіді
answer-decimal-comma = рядок { $line }: у { $text } десяткова кома; кожна клітинка — ціле число (клітинки розділяються пробілами)
grade-mistakes-more = ще клітинок, у яких помилилися двоє або більше студентів, не показано: { $count }
check-hint-other-buffer = це точно { $other }, а не { $buffer }: чи не здано його як інший буфер?
