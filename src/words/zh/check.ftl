# zsim's words in Chinese: checking and grading answers, gradebooks, exercises.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

check-all-match = { $buffer } { $file }：{ $after } 之后全部 { $cells } 个单元都正确
check-differ = { $buffer } { $file }：{ $after } 之后，{ $cells } 个单元中有 { $count } 个不同
check-unanswered = ；{ $cells } 个单元中有 { $count } 个未作答（? 或 .）
check-hint-matches = 提示：如果按{ $how }读取，答案完全正确；请先写最上面一行（y = { $top }），每行从 x = 0 写起，与教材的印法相同
check-hint-fewer = 提示：如果按{ $how }读取，只有 { $left } 个单元不同；请先写最上面一行（y = { $top }），每行从 x = 0 写起，与教材的印法相同
check-column-answer = 答案
check-column-right = 正确值
check-column-why = 原因
check-in-arith = 在 { $arith } 运算中该单元为 { $mode }；在精确运算中为 { $exact }：{ $reason }
grade-summary = 班级 { $class }，场景 { $scene }，{ $polygon }之后：{ $students } 名学生；正确 { $ok }，有错 { $wrong }，文件有误 { $malformed }，缺少答案 { $missing }
grade-column-student = 学生
grade-column-frame = 帧缓冲器错误
grade-column-depth = z缓冲器错误
grade-column-score = 得分 %
grade-column-status = 结果
grade-column-buffer = 缓冲器
grade-column-wrong = 出错人数
grade-column-answered = 作答
grade-status-ok = 正确
grade-status-wrong = 有错
grade-status-incomplete = 未完成：{ $count } 个单元未作答
grade-status-malformed = 文件有误：{ $why }
grade-status-missing = 缺少：{ $what }
grade-students-of = { $total } 人中 { $count } 人
grade-mistakes = 常见错误（至少两名学生答错的单元，按人数从多到少）：
grade-mistakes-none = 常见错误：没有哪个单元被两名以上学生答错
grade-feedback = { $student }：{ $scene }，{ $polygon }之后：得分 { $score } %，{ $status }
exercise-title = 练习，种子 { $seed }：{ $width }×{ $height } 栅格，{ $count } 个多边形
exercise-solution-title = 练习，种子 { $seed }：最后一个多边形之后的帧缓冲器
exercise-task-draw = 用 z 缓冲器算法按顺序（先画 A）绘制各多边形：z 越大越近；z 缓冲器初值为 0，取值 0 … { $max }（四舍五入，超出范围取边界值）。
exercise-task-write = 写出最后一个多边形之后的帧缓冲器（各多边形的值）和 z 缓冲器，从最上一行写起。
misreading-upside-down = 从最下面一行开始的顺序
misreading-transposed = 行列互换的方式
answer-at-cell = 第 { $line } 行第 { $column } 个数（x = { $x }，y = { $y }）
answer-at = 第 { $line } 行第 { $column } 个数
answer-not-a-number = { $at }：“{ $cell }”不是整数（{ $buffer }的取值为 0 … { $max }）
answer-too-large = { $at }：{ $value } 超出{ $buffer }的范围（0 … { $max }）
answer-row-length = 第 { $line } 行：有 { $count } 个数，而光栅宽度为 { $width }
answer-row-count = 共 { $count } 行，而光栅有 { $height } 行
answer-frame-range = { $bits } 位帧缓冲器
answer-depth-range = { $bits } 位z缓冲器
case-line = 第 { $line } 行：{ $problem }
case-unknown-command = 未知命令“{ $command }”
case-keyword-problem = { $keyword }：{ $problem }
exercise-notes-settings = 练习：种子 { $seed }，{ $width }×{ $height } 光栅，{ $polygons } 个多边形，帧缓冲 { $frame_bits } 位，z 缓冲 { $depth_bits } 位（0 … { $max }），深度测试 { $test }
exercise-notes-asked = 要求：{ $asked }（种子序列中的第 { $candidate } 个候选）
exercise-notes-no-case = 无特定情形
exercise-notes-contains = 包含（在运行轨迹中找到，各取第一处）：
exercise-notes-none = 没有难点情形
exercise-notes-next = 检查答案：zsim check { $path } --frame FRAME.txt --depth DEPTH.txt；给全班评分：zsim grade { $path } CLASS_DIR
diagnosis = 可能的原因：{ $what }（解释了 { $wrong } 个错误单元中的 { $explained } 个）
grade-column-cause = 可能的原因
grade-cause = { $what }（{ $wrong } 个中的 { $explained } 个）
grade-causes = 全班可能的原因：
grade-cause-count = { $what }：{ $students } 名学生中有 { $count } 名
answer-more-problems = { "" } · 另有 { $count } 处问题
gradescope-test = { $after } 之后的{ $buffer }
expect-not-states = “{ $text }”不是状态列表：请写 final、each，或用逗号分隔、从 1 开始的多边形编号（1,3）
gradescope-missing = 没有文件回答这一项：请提交 { $file }
gradescope-score-rule = 得分：场景改变的 { $changed } 个单元中答对的比例（{ $right } 个），每有一个单元在缓冲区应保持初始值处被写入（共 { $stray } 个）就减去同样一份；未作答的单元不计
gradescope-ambiguous = { $files } 都回答这一项：均不评分；只交一个
gradescope-unused = 未评分（作业不要求这些文件）：{ $files }
check-more-cells = …… 另有 { $count } 个单元格不同，未列出
grade-skipped = 未评分：{ $file } 不是答案文件（应为 姓名.frame.txt 或 姓名.depth.txt）
grade-skipped-near = 未评分：{ $file } 看起来是 { $student } 的{ $buffer }：请命名为 { $name }
answer-grid-label = 在网格中输入（从清空的缓冲开始）
answer-empty = 文件为空：其中没有答案的任何一行
answer-decimal-comma = 第 { $line } 行：{ $text } 含有小数逗号；每个单元格是一个整数（单元格之间用空格分隔）
grade-mistakes-more = 另有 { $count } 个两名或更多学生答错的单元格未列出
check-hint-other-buffer = 这正是{ $other }，而不是{ $buffer }：是否把它当作另一个缓冲区交上来了？
