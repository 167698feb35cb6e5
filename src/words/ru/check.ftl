# zsim's words in Russian: checking and grading answers, gradebooks, exercises.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

check-all-match = { $buffer } { $file }: совпадает с верным ответом после { $after } (ячеек: { $cells })
check-differ = { $buffer } { $file }: { $count ->
    [one] отличается { $count } ячейка
    [few] отличаются { $count } ячейки
   *[many] отличаются { $count } ячеек
  } из { $cells } после { $after }
check-unanswered = ; без ответа (? или .) { $count ->
    [one] оставлена { $count } ячейка
    [few] оставлены { $count } ячейки
   *[many] оставлено { $count } ячеек
  } из { $cells }
check-hint-matches = подсказка: если читать { $how }, ответ совпадает; записывайте сначала верхнюю строку (y = { $top }), каждую строку от x = 0, как в книге
check-hint-fewer = подсказка: если читать { $how }, расхождений остаётся: { $left }; записывайте сначала верхнюю строку (y = { $top }), каждую строку от x = 0, как в книге
check-column-answer = ответ
check-column-right = верно
check-column-why = почему
check-in-arith = в арифметике { $arith } в ячейке { $mode }; в точной арифметике { $exact }: { $reason }
grade-summary = класс { $class }, сцена { $scene }, после { $polygon }: { $students ->
    [one] { $students } студент
    [few] { $students } студента
   *[many] { $students } студентов
  }; верно: { $ok }, с ошибками: { $wrong }, с негодными файлами: { $malformed }, без ответа: { $missing }
grade-column-student = студент
grade-column-frame = ошибок в буфере кадра
grade-column-depth = ошибок в z-буфере
grade-column-score = баллы, %
grade-column-status = итог
grade-column-buffer = буфер
grade-column-wrong = ошиблись
grade-column-answered = ответы
grade-status-ok = верно
grade-status-wrong = с ошибками
grade-status-incomplete = не закончено: { $count ->
    [one] { $count } ячейка оставлена
    [few] { $count } ячейки оставлены
   *[many] { $count } ячеек оставлено
  } без ответа
grade-status-malformed = негодный файл: { $why }
grade-status-missing = нет файла: { $what }
grade-students-of = { $count } из { $total }
grade-mistakes = частые ошибки (ячейки, в которых ошиблись хотя бы двое, сначала самые частые):
grade-mistakes-none = частые ошибки: ни в одной ячейке не ошиблись двое или больше
grade-feedback = { $student }: { $scene }, после { $polygon }: { $score } %, { $status }
exercise-title = упражнение, seed { $seed }: растр { $width }×{ $height }, { $count ->
    [one] { $count } многоугольник
    [few] { $count } многоугольника
   *[many] { $count } многоугольников
  }
exercise-solution-title = упражнение, seed { $seed }: буфер кадра после последнего многоугольника
exercise-task-draw = Нарисуйте многоугольники по порядку (сначала A) алгоритмом z-буфера: чем больше z, тем ближе; z-буфер вначале заполнен нулями и хранит 0 … { $max } (с округлением и насыщением).
exercise-task-write = Запишите буфер кадра (значение каждого многоугольника) и z-буфер после последнего многоугольника, начиная с верхней строки.
misreading-upside-down = с нижней строки
misreading-transposed = по столбцам (строки и столбцы переставлены)
answer-at-cell = строка { $line }, число { $column } (x = { $x }, y = { $y })
answer-at = строка { $line }, число { $column }
answer-not-a-number = { $at }: «{ $cell }» — не целое число ({ $buffer } хранит 0 … { $max })
answer-too-large = { $at }: { $value } не помещается в { $buffer } (0 … { $max })
answer-row-length = строка { $line }: { $count ->
    [one] { $count } число
    [few] { $count } числа
   *[many] { $count } чисел
  }, а ширина растра { $width }
answer-row-count = строк { $count }, а у растра их { $height }
answer-frame-range = { $bits }-битный буфер кадра
answer-depth-range = { $bits }-битный z-буфер
case-line = строка { $line }: { $problem }
case-unknown-command = неизвестная команда «{ $command }»
case-keyword-problem = { $keyword }: { $problem }
exercise-notes-settings = упражнение: зерно { $seed }, растр { $width }×{ $height }, многоугольников { $polygons }, буфер кадра { $frame_bits } бит, z-буфер { $depth_bits } бит (0 … { $max }), тест глубины { $test }
exercise-notes-asked = заказано: { $asked } (кандидат { $candidate } из последовательности зерна)
exercise-notes-no-case = никакого особого случая
exercise-notes-contains = содержит (найдено в трассе прогона, первое место каждого):
exercise-notes-none = ни одного трудного случая
exercise-notes-next = проверить ответ: zsim check { $path } --frame FRAME.txt --depth DEPTH.txt; оценить группу: zsim grade { $path } CLASS_DIR
diagnosis = вероятная причина: { $what } (объясняет { $explained } из { $wrong } { $wrong ->
    [one] неверной ячейки
   *[other] неверных ячеек
})
grade-column-cause = вероятная причина
grade-cause = { $what } ({ $explained } из { $wrong })
grade-causes = вероятные причины в группе:
grade-cause-count = { $what }: { $count } из { $students } { $students ->
    [one] студента
   *[other] студентов
}
answer-more-problems = { "" } · и ещё { $count } { $count ->
    [one] ошибка
    [few] ошибки
   *[many] ошибок
}
gradescope-test = { $buffer } после { $after }
expect-not-states = «{ $text }» — не список состояний: напишите final, each или номера многоугольников от 1 через запятую (1,3)
gradescope-missing = нет файла с этим ответом: сдайте { $file }
gradescope-score-rule = оценка: доля верных ({ $right }) среди { $changed } ячеек, которые сцена меняет, минус такая же доля за каждую из { $stray } ячеек, записанных там, где буфер сохраняет начальное значение; ячейки без ответа не учитываются
gradescope-ambiguous = на это отвечают сразу { $files }: ни один не оценён; сдайте один
gradescope-unused = не оценены (задание их не требует): { $files }
check-more-cells = … и ещё { $count } { $count ->
    [one] ячейка отличается
    [few] ячейки отличаются
   *[other] ячеек отличаются
}, не перечислены
grade-skipped = не проверен: { $file } — не файл ответа (ИМЯ.frame.txt или ИМЯ.depth.txt)
grade-skipped-near = не проверен: { $file } похож на { $buffer } ученика { $student }: назовите его { $name }
answer-grid-label = Ввести в сетку (начиная с очищенного буфера)
answer-empty = файл пуст: в нём нет ни одной строки ответа
answer-decimal-comma = строка { $line }: в { $text } десятичная запятая; каждая ячейка — целое число (ячейки разделяются пробелами)
grade-mistakes-more = ещё ячеек, в которых ошиблись двое или больше студентов, не показано: { $count }
check-hint-other-buffer = это в точности { $other }, а не { $buffer }: не сдан ли он как другой буфер?
