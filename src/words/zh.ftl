# zsim 的简体中文用语，沿用教材（消隐、Z缓冲区算法）的术语：
# 像素、帧缓冲器、z缓冲器、多边形、扫描线。

buffer-frame = 帧缓冲器
buffer-depth = z缓冲器
polygon-name = { $named ->
    [yes] 多边形 { $number }“{ $name }”
   *[no] 多边形 { $number }
}
polygon-after = { $named ->
    [yes] 多边形 { $number }“{ $name }”
   *[no] 多边形 { $number }
}
span = { $left } … { $right }
scanline = y = { $y }
list-and = { " 和 " }
list-semicolon = { "；" }
list-comma = { "，" }

winding-cw = 顺时针
winding-ccw = 逆时针

stored-whole = 向z缓冲器写入 { $stored }
stored-rounded-up = 向z缓冲器写入 { $stored }（{ $value } 向上舍入为 { $stored }）
stored-rounded = 向z缓冲器写入 { $stored }（{ $value } 舍入为 { $stored }）
stored-saturated = 向z缓冲器写入 { $stored }（{ $value } 舍入为 { $rounded }，再截断为 { $stored }）
stored-exact = 向z缓冲器写入 { $stored }（精确值）

z-w-buffer = { $w }（w缓冲器使用的观察坐标系深度；投影后 z' = { $z }）
z-projected = { $z }（投影后的 z'；观察坐标系深度 w = { $w }）
z-beyond = （超出 128 位精确运算的范围）

test-passed = { $z } { $op } { $stored }
test-failed = { $z }，不满足 z { $op } { $stored }
test-uncompared = { $z }（深度测试 { $test }；z缓冲器中原值为 { $stored }）
rule-compared = z { $op } z缓冲器中的值
rule-always = 所有片元都通过
rule-never = 没有片元通过

frame-blended = { $frame }（不透明度 { $alpha }：{ $alpha }·{ $value } + { $rest }·{ $under }（下层），四舍五入）
reason-written = z = { $test }，因此{ $stored }，并向帧缓冲器写入 { $frame }
reason-hidden = z = { $test }：被遮挡，不作任何改变
reason-outside-range = z = { $z } 超出深度范围 { $front } … { $rear }：被丢弃
reason-beyond-section = z = { $test }，但剖切只保留 z { $op } { $section } 的部分：不写入

fate-culled = 被剔除：其顶点按{ $winding }方向排列，因此不绘制
fate-edge-on = 侧对视点（c = 0）：不覆盖任何像素
fate-degenerate = 退化（Newell 法向量为零）：不覆盖任何像素
fate-clipped = 所有顶点都在近平面之后：被完全裁剪，不绘制

entry-no-row = 其 y 范围不到达扫描线 { $scanline }{ $tie }
entry-covered = 在扫描线 { $scanline } 上它的区段是 { $span }，包含像素中心 x = { $centre }{ $tie }；{ $reason }
entry-covered-no-span = 在扫描线 { $scanline } 上它包含像素中心 x = { $centre }{ $tie }；{ $reason }
entry-not-inside = 在扫描线 { $scanline } 上{ $spans }；像素中心 x = { $centre } 不在其中{ $tie }
spans-none = { $subject }与该扫描线没有交点
spans-some = { $subject }的区段是 { $spans }
subject-it = 它
tie-wrap = { "（" }{ $text }）

why-covers = { $polygon } 覆盖 ({ $x }, { $y })：z = { $test }，因此{ $result }
why-later = { "；之后 " }{ $list }
why-later-item = { $polygon }（{ $reason }）
result-frame = 帧缓冲器中为 { $value }
cleared-frame = 背景值 { $value }
cleared-depth = 初始深度 { $value }
why-covered-item = { $polygon } 覆盖该像素，但{ $reason }
why-nothing-written = ({ $x }, { $y }) 处没有写入任何值：{ $list }；保持{ $cleared }
why-none-reaches = 没有多边形覆盖 ({ $x }, { $y })：没有多边形到达扫描线 { $scanline }；保持{ $cleared }
why-not-covered = 没有多边形覆盖 ({ $x }, { $y })：在扫描线 { $scanline } 上{ $list }；保持{ $cleared }

boundary-top = 上边
boundary-bottom = 下边
boundary-left = 左边
boundary-right = 右边
boundary-vertex = 顶点
tie-vertex = 像素中心恰好是顶点 { $point }：由在此相交的边决定，依据{ $rule }
tie-edge-in = 像素中心恰好位于从 { $a } 到 { $b } 的{ $boundary }上，{ $rule }将其包含在内
tie-edge-out = 像素中心恰好位于从 { $a } 到 { $b } 的{ $boundary }上，{ $rule }将其排除在外
rule-columns-centre = 教材的列规则（中心在 [x_l, x_r] 内，含端点）
rule-columns-cell = BUET 的列规则（从含 x_a 的单元到含 x_b 的单元）
rule-columns-half-open = 半开列规则（中心在 [x_l, x_r) 内：含左边，不含右边）
rule-rows-half-open = 教材的半开区间规则（边在 min ≤ y < max 时计入）
rule-rows-closed = BUET 的闭区间行规则（min ≤ y ≤ max）
rule-rows-top-left = 左上规则（边在 min < y ≤ max 时计入：含上边，不含下边）

explain-heading = 场景 { $file } 的像素 ({ $x }, { $y })：中心 ({ $cx }, { $cy })，深度测试 { $test }（{ $rule }）
polygon-line = { $polygon }：{ $text }
explain-start = 开始：帧缓冲器 { $frame }，z缓冲器 { $depth }（已清除）
explain-final = 结果：帧缓冲器 { $frame }，z缓冲器 { $depth }

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

## run 与 step：场景标题、各阶段、多边形标题

depth-test-greater = 大于
depth-test-less = 小于
depth-test-greater-equal = 大于等于
depth-test-less-equal = 小于等于
depth-test-always = 总是
depth-test-never = 从不
scene-header = 场景 { $path }：{ $width }×{ $height } 像素，帧缓冲器 { $frame_bits } 位，z缓冲器 { $depth_bits } 位（0…{ $depth_max }），深度测试 { $test }（{ $rule }），初值 { $clear }
scene-stages = 阶段：{ $stages }
scene-effects = 效果：{ $effects }
effects-none = 无
stage-cull = 背面剔除（跳过{ $winding }的多边形）
stage-near-plane = 近平面裁剪（保留 z ≤ { $near }）与透视投影（视点在 z = { $eye }）
stage-supersampling-sample = { $k }×{ $k } 超采样（每个采样点取深度），然后求平均
stage-supersampling-pixel = { $k }×{ $k } 超采样（在像素中心取深度），然后求平均
stage-window = 窗口 { $left } … { $right } × { $bottom } … { $top } 映射到光栅
stage-scan = 扫描转换
stage-scan-closed = 扫描转换（闭区间行，取包含交点的单元）
stage-scan-top-left = 扫描转换（左上规则）
stage-depth-range = 深度范围（丢弃 { $front } … { $rear } 之外的 z）
stage-w-buffer = w缓冲器（观察坐标系深度 z = d·z'/(d + z')）
stage-depth-test = 深度测试（{ $rule }）
stage-section = 剖切（z { $op } { $section }）
stage-blend = 按不透明度混合（α·值 + (1 − α)·下层，四舍五入）
stage-store-quantized = 写入（四舍五入，截断到 0…{ $max }）
stage-store-exact = 写入（精确深度）
heading-start = { $polygon }（值 { $value }）
heading-degenerate = { $start }：退化：Newell 法向量为零（顶点共线，或环路相互抵消），因此没有平面，不覆盖任何像素
heading-clipped-away = { $start }：在近平面之后：被完全裁剪，不绘制
heading-edge-on = { $start }：平面 { $plane }：侧对视点（c = 0），不覆盖任何像素
heading-culled = { $start }：平面 { $plane }，{ $winding }：被剔除（cull { $cull }），不绘制
heading-drawn = { $start }：平面 { $plane }{ $winding }{ $opacity }{ $clipped }
heading-drawn-projected = { $start }：投影后的平面 { $plane }{ $winding }{ $opacity }{ $clipped }
heading-winding = { "，" }{ $winding }
heading-opacity = { "，不透明度 " }{ $alpha }
heading-clipped = { "；" }{ $of } 个顶点中有 { $front } 个在近平面之前，按 { $n } 边形绘制
run-counts = 覆盖像素中心 { $covered } 个，写入 { $written } 个
run-frame-after = { $polygon }之后的帧缓冲器：
run-depth-after = { $polygon }之后的z缓冲器：
run-no-polygons = 场景中没有多边形：缓冲器保持清除后的状态
run-frame-cleared = 清除后的帧缓冲器：
run-depth-cleared = 清除后的 z 缓冲器：
figure-title-worksheet = { $file }：待绘制的多边形，栅格为空
figure-title-after = { $file }：{ $polygon }之后的{ $buffer }
figure-title-samples = { "，" }每个像素 { $k }×{ $k } 个采样，平均之前（平均值由 `zsim run` 给出）
figure-cell = ({ $x }, { $y })：帧缓冲器 { $frame }，z缓冲器 { $depth }
figure-cells = ({ $from } … { $to }, { $y })：帧缓冲器 { $frame }
figure-background = { $value }：背景
figure-value = 值 { $value }
figure-value-named = 值 { $value }：{ $names }
figure-polygons = { $count } 个多边形
figure-axis-x = x（数字标在像素中心，x + ½）
figure-cleared = 清除值（{ $value }）
figure-far = { $larger_nearer ->
    [yes] z 较小：较远
   *[no] z 较大：较远
}
figure-near = { $larger_nearer ->
    [yes] z 较大：较近
   *[no] z 较小：较近
}
file-written-about = 已写入 { $path }（{ $about }）
file-written-page = 已写入 { $path }（用浏览器打开；无需网络）

## 逐行的 step

step-slope = 沿扫描线 z 每步变化 −a/c = { $slope }
step-scanline = 扫描线 { $scanline }（光栅第 { $row } 行）
step-crossings = 交点：{ $list }
step-crossings-none = 无
step-span = 区段 { $n }：x_a = { $xa }，z_a = { $za }；x_b = { $xb }，z_b = { $zb }；{ $columns }
step-columns = 列 { $first } … { $last }
step-no-column = 不含任何列
step-col-centre = 中心
step-col-step = 步长
step-col-stored = 原值
step-col-test = 测试
step-col-after = 之后
step-col-frame = 帧
step-start = 起点
step-written = { $test }：写入
step-hidden = { $test }：被遮挡
step-test-written = { $z } { $op } { $stored }：写入
step-test-hidden = { $z } { $op } { $stored }：否，被遮挡
step-beyond-section = { $op } { $stored }，在剖切面之外
step-outside-range = { $z }：超出深度范围，被丢弃
step-tie = x = { $x } 处的边界情形：{ $text }
step-frame-after = 本扫描线之后的帧缓冲器（第 { $low } … { $high } 行）：
step-depth-after = 本扫描线之后的z缓冲器（第 { $low } … { $high } 行）：
step-end = 场景结束：没有更多扫描线（b 后退，q 退出）
step-first = 已经是第一条扫描线
step-outside-raster = 第 { $row } 行不在光栅内（行 0 … { $last }）
step-not-reach = { $polygon } 不到达扫描线 { $scanline }
step-unknown = 未知命令“{ $text }”；{ $help }
step-prompt = { "zsim step> " }

## 终端中的 step：全屏界面

tui-title = zsim step ·{ $heading } · { $view }{ $score } · ? 按键
tui-heading = { " " }{ $polygon }，扫描线 { $scanline }
tui-heading-end = { " 场景结束" }
tui-score = { " · 测验 " }{ $right }/{ $asked }
tui-key-nothing = 这个键在这里不起作用：按 ? 查看按键
tui-no-later = 后面没有覆盖像素的多边形
tui-no-earlier = 前面没有覆盖像素的多边形
tui-go = 转到该行的扫描线：{ $text }▏（Enter 转到，Esc 取消）
tui-status = n/→ 下一步 · b/← 后退 · p/P 多边形 · g 转到 · f/z 缓冲器 · m 逐像素 · q 退出
tui-no-scanline = 没有扫描线
tui-columns-shown = 显示 x { $first } … { $last }（全部 0 … { $max }）
tui-end = 场景结束
tui-span = 区段 { $n }：{ $left } … { $right }；{ $columns }
tui-no-centre = 不含任何像素中心
tui-table-heading = x { $z } 测试 → 写入值（帧）
tui-uncompared = { $test } 通过，
tui-not = { "不满足 " }
tui-hidden = 被遮挡
tui-pixel-by-pixel = m：逐像素显示，附原因
tui-steps-from = { "，从 " }{ $start } 起走了 { $count } 步 −a/c
tui-pixel = ({ $x }, { $y })：中心 x = { $centre }，z = { $z }{ $steps }
tui-keys = { " 按键 " }
tui-help =
    n Space Enter → ↓  下一条扫描线（或下一个像素）
    b ← ↑              后退
    p / P              下一个 / 上一个多边形
    g                  转到某行的扫描线
    f / z              显示帧缓冲器 / z缓冲器
    m                  逐像素 / 逐扫描线
    PgUp PgDn < >      滚动光栅
    { "[ ]" }                滚动表格
    ?                  显示这些按键（按任意键关闭）
    q Esc Ctrl-C       退出

    黄色：区段内被覆盖的像素
    青色：本多边形此前写入的像素

## 测验（step --quiz）

quiz-mistakes = 你的错误：
meant-not-written = 不写入
meant-value-written = 写入的值
meant-value-kept = 不写入：保持原值
meant-value = 一个值
quiz-coverage-hint = 请输入被覆盖的列，格式为 起-止（多段用空格分开：3-5 9-12），没有则输入 -
quiz-coverage-why = 区段为 { $spans }；某列的中心 x + 1/2 落在区段内时，该列被覆盖
quiz-coverage-mistake = { $polygon } 的第 { $row } 行：你的答案是列 { $said }，正确为 { $right }：{ $why }
quiz-depth-hint = 请输入 z缓冲器将保存的值，不写入则输入 -（q 结束测验）
quiz-not-an-answer = “{ $text }”不是答案：{ $hint }
quiz-does-not-fit = { $text } 放不进这个 z 缓冲器：它的单元只存 0 … { $max } 的整数级；请重新输入
quiz-keeps = -（保持 { $value }）
quiz-depth-mistake = { $polygon } 的 ({ $x }, { $y })：你的答案 { $said }，正确为 { $right }：{ $reason }

## step --html：网页

page-back = ◀ 后退 (b)
page-next = 下一步 ▶ (n)
page-previous-polygon = ◀◀ 多边形 (P)
page-next-polygon = 多边形 ▶▶ (p)
page-frame = 帧缓冲器 (f)
page-depth = z缓冲器 (z)
page-quiz = 测验
page-no-pixel = 此场景不覆盖任何像素。
page-frame-after = 本扫描线之后的帧缓冲器
page-depth-after = 本扫描线之后的z缓冲器
page-column-stored = 原值
page-column-after = 之后的 z缓冲器值
page-column-why = 原因
page-keeps = –（保持 { $value }）
page-check = 检查答案
page-status = 第 { $at } 条扫描线，共 { $count } 条

## 学生最常遇到的错误：文件、多边形、答案

error-read = { $path }：无法读取：{ $reason }
error-write = { $path }：无法写入：{ $reason }
error-polygon = { $path }：{ $polygon }：{ $problem }
geometry-too-few = 只有 { $count } 个顶点；多边形至少需要 3 个
geometry-too-many = 有 { $count } 个顶点；zsim 最多接受 { $max } 个
geometry-out-of-range = 顶点 { $vertex } 的坐标 { $value } 超出精确范围：多边形的公分母为 { $denominator }，|坐标| × 2 × { $denominator } 不得超过 2^4096（请使用更小的坐标或更少的小数位）
digits = { $count } 位
geometry-off-plane-z = 不共面：顶点 { $vertex } 偏离经过顶点 { $i }、{ $j }、{ $k } 的平面 { $plane }，Δz = { $off }
geometry-off-plane = 不共面：顶点 { $vertex } 代入经过顶点 { $i }、{ $j }、{ $k } 的平面 { $plane } 得 { $off } 而不是 0
answer-at-cell = 第 { $line } 行第 { $column } 个数（x = { $x }，y = { $y }）
answer-at = 第 { $line } 行第 { $column } 个数
answer-not-a-number = { $at }：“{ $cell }”不是整数（{ $buffer }的取值为 0 … { $max }）
answer-too-large = { $at }：{ $value } 超出{ $buffer }的范围（0 … { $max }）
answer-row-length = 第 { $line } 行：有 { $count } 个数，而光栅宽度为 { $width }
answer-row-count = 共 { $count } 行，而光栅有 { $height } 行
answer-frame-range = { $bits } 位帧缓冲器
answer-depth-range = { $bits } 位z缓冲器

## explain 的补充：剖切、分段、内部测试、反走样、其他运算

explain-section = 剖切：只写入 z { $op } { $section } 的部分
explain-inside = 像素中心的内部测试：射线法判定为{ $ray }；角度和法：{ $arc }
explain-inside-in = 内部
explain-inside-out = 外部
explain-arc-boundary = 在边界上，因此算内部
explain-arc-winding = 环绕数 { $winding }，因此在{ $inside }
explain-segment = 分段 { $number }/{ $count }（{ $segments }）：列 { $first } … { $last }，行 { $bottom } … { $top }；其z缓冲器有 { $cells } 个单元；涉及 { $visited }
explain-segment-none = 无多边形
explain-antialias = 反走样，{ $k }×{ $k } 个采样点（上面几行是不做反走样时的像素中心；采样点以 1/{ $k } 像素为单位）
explain-sample = 采样点 ({ $i }, { $j }) 位于 ({ $x }, { $y })：帧缓冲器 { $frame }，z缓冲器 { $depth }
explain-pixel-mode = { $polygon } 覆盖采样点 { $samples }；其平面在像素中心的深度为 { $depth }：{ $result }
explain-pixel-mode-written = 写入，z缓冲器为 { $stored }，这些采样点取该值
explain-pixel-mode-not-written = 不写入
explain-mean = 采样平均：帧缓冲器 { $frame }，z缓冲器 { $depth }
explain-arith = 在 { $arith } 运算中：帧缓冲器 { $frame }，z缓冲器 { $depth }（{ $verdict }）
explain-arith-same = 与精确运算相同
explain-arith-differs = 与精确运算结果不同

## 裁剪空间顶点 [x, y, z, w]

vertex-decimal-comma = 一个顶点有四个数 { $written }，而其他顶点是 [x, y, z]：{ $comma } 是小数逗号吗？JSON 的小数用小数点：请写 { $meant }
clip-space-mixed = 同时使用了 [x, y, z] 顶点和裁剪空间的 [x, y, z, w] 顶点：同一多边形的顶点请用同一种写法
clip-space-alone = 使用裁剪空间顶点 [x, y, z, w]，由视口变换映射到光栅上；它们不能与窗口或透视效果同时使用
fate-outside-view = 它位于视见体（−w ≤ x, y, z ≤ w）之外：被完全裁剪，不绘制
heading-outside-view = { $start }：位于视见体（−w ≤ x, y, z ≤ w）之外：被完全裁剪，不绘制
heading-view = { "；裁剪空间：" }{ $of } 个顶点中有 { $inside } 个在视见体内，经裁剪、除以 w 和视口变换后按 { $n } 边形绘制

## 读取场景

scene-not-object = 场景应是形如 {"{"}"width": 32, "height": 32, "polygons": [...]{"}"} 的 JSON 对象，而不是{ $found }
json-array = 数组
json-string = 字符串
json-number = 数字
json-bool = true 或 false
json-null = null
json-comma-end = { "（第 " }{ $line } 行末尾缺少逗号）
json-comma-after = { "（第 " }{ $line } 行第 { $column } 列之后缺少逗号）
json-invalid = 不是有效的 JSON：{ $error }
location-polygon = 多边形 { $number }
number-found-object = 应为数字，实际是对象
number-found-bool = 应为数字，实际是布尔值
number-found-null = 应为数字，实际是 null
number-found-list = 应为数字，实际是列表
number-not-a-number = “{ $text }”不是数字（请写整数、像 2.5 这样的小数或像 "5/2" 这样的分数）
number-zero-denominator = “{ $text }”除以零
number-too-large = “{ $text }”的位数太多，无法精确保存（最多 30 位有效数字）
number-too-long = “{ $text }”的位数太多或十的幂太大（顶点坐标最多 { $max } 位有效数字，十的幂不超过 ±{ $max }）
setting-bits = 不支持 { $value }：请使用 1 到 32 位
setting-side-zero = 至少应为 1 像素
setting-side-large = { $side } 超过了 { $max } 像素的上限
setting-cells = { $width }×{ $height } 共 { $cells } 像素，超过了上限 { $max }
setting-background = { $value } 超出 { $bits } 位帧缓冲器的范围（最大 { $max }）
setting-window = 左边界 { $left } 应小于右边界 { $right }，下边界 { $bottom } 应小于上边界 { $top }
setting-depth-range = [{ $front }, { $rear }]：前界不得大于后界
setting-clear-depth = 只适用于精确z缓冲器（规则中 "store": "exact"）；量化的z缓冲器清除为最远的级别
setting-perspective-positive = 透视：distance 和 near 必须为正
setting-antialias-samples = 反走样：不支持 { $samples } 个采样：请使用 1 到 16
setting-antialias-cells = 反走样：{ $width }×{ $height } 像素 × { $samples }² 个采样超过了 { $max } 个单元的上限
setting-antialias-exact = 反走样对量化的z缓冲器求平均；不能与精确保存同时使用
polygon-opacity = 不透明度 { $alpha } 不在 0 … 1 之内
polygon-value-too-wide = 值 { $value } 超出 { $bits } 位帧缓冲器的范围（最大 { $max }）

origin-supersampled = 超采样 { $factor }× 后的场景
origin-snapped = 对齐到 fixed:{ $bits } 后的场景

usage-arith-plain-rules = --arith { $arith } 按教材规则模拟基本算法；此场景要求其他规则或逐像素效果（请用 --arith exact）
usage-arith-greater-or-less = --arith { $arith } 只模拟 greater 和 less 两种深度测试；此场景要求 { $test }（请用 --arith exact）
usage-arith-plain-loop = exact 以外的 --arith 运行基本的 z 缓冲循环；请去掉 --segments 和 --order
usage-no-polygon-numbered = 没有多边形 { $number }：场景共有 { $count } 个（从 1 开始编号）
usage-no-polygon-named = 没有名为“{ $name }”的多边形：场景中有 { $names }
usage-pixel-outside = 像素 ({ $x }, { $y }) 在 { $width }×{ $height } 光栅之外（x 0 … { $last_x }，y 0 … { $last_y }）
usage-figure-format = { $path }：图只能写成 .svg、.png、.pdf 或 .tex（TikZ）
usage-figure-too-large = { $path }：图最多画 { $max }×{ $max } 的光栅；此光栅为 { $width }×{ $height }
usage-png-failed = { $path }：无法绘制图：{ $reason }
usage-no-polygons-draw = { $path }：场景中没有可画的多边形
usage-no-polygons-grade = { $path }：场景中没有可评分的多边形
usage-no-polygons-check = { $path }：场景中没有可检查的多边形
usage-exact-depths-grade = { $path }：此场景保存精确深度，其 z 缓冲没有可评分的整数矩阵；请评分帧缓冲
usage-exact-depths-check = { $path }：此场景保存精确深度，其 z 缓冲没有可检查的整数矩阵；请检查帧缓冲，或用 `zsim buet check` 检查 BUET 的 z_buffer.txt
usage-check-needs-answer = 检查需要答案：--frame 文件 和/或 --depth 文件
usage-no-answers = { $path }：未找到答案：请把每个学生的文件命名为 姓名.frame.txt 和/或 姓名.depth.txt
usage-scenes-range = --scenes 取 1 到 100
usage-memory-bits = { $option } { $bits }：请用 1 到 64 位
usage-memory-zero = --width、--height 和 --supersample 至少为 1
usage-memory-too-large = 光栅太大，无法计数（超过 2^50 个单元）
usage-random-count = --count { $count }：最多 { $max } 个三角形（这么大的场景读回约需 10 GB）
usage-random-bits = --frame-bits 和 --depth-bits 取 1 到 32
usage-random-side = --width 和 --height 取 1 到 { $max }
usage-not-a-hard-case = --hard：“{ $name }”不是难点情形：{ $names }
usage-exercise-size = --size { $width }x{ $height }：练习的每边为 4 … 64 个像素
usage-exercise-polygons = --polygons { $count }：练习有 1 … 8 个多边形
usage-exercise-bits = 手算练习中 --frame-bits 取 1 … 8，--depth-bits 取 1 … 16
usage-exercise-two-polygons = hidden 和 intersecting 需要两个或更多多边形（--polygons 2）
usage-exercise-not-found = 在 { $tries } 次尝试中没有出现 { $width }×{ $height } 上含 { $polygons } 个多边形且包含全部 { $cases } 的场景；请减少情形、增加多边形或加大光栅
usage-inside-needs-pixel-order = --inside 选择 --order pixels 的点在多边形内测试；请加上 --order pixels
usage-tiles-need-format-none = --tile 和 --threads 只适用于 --format none、--final 和 --after（否则按顺序显示每个多边形画完后的状态）
usage-format-none-is-plain = --format none 汇总 z 缓冲循环；带 --segments、--order pixels 或抗锯齿时请用 text 或 json
usage-no-scanlines = { $polygon } 没有扫描线：{ $why }
usage-scanline-rows = { $reach }：它的行为 { $first } … { $last }
usage-scanline-no-rows = { $reach }：它不到达光栅的任何一行

step-skip-fate = { $polygon }：{ $why }
step-skip-no-scanline = { $polygon }：不到达光栅的任何扫描线
step-skip-no-centre = { $polygon }，扫描线 { $scanline }：没有覆盖任何像素中心
step-skip-no-centre-no-crossings = { $polygon }，扫描线 { $scanline }：没有覆盖任何像素中心（没有交点）

case-line = 第 { $line } 行：{ $problem }
case-unknown-command = 未知命令“{ $command }”
case-keyword-problem = { $keyword }：{ $problem }
list-or = { $rest } 或 { $last }
cs418-second-png = 第二个“png”行（文件只在第一行指定一张图像）
cs418-before-png = “{ $keyword }”出现在必须位于首行的“png WIDTH HEIGHT FILE”之前
cs418-flag-numbers = “{ $keyword }”不带数字，却有 { $found } 个
cs418-fsaa = fsaa { $level }：级别须为 1 到 8
cs418-size = { $keyword } { $size }：大小须为 { $allowed }
cs418-not-an-index = elements：“{ $word }”不是索引（≥ 0 的整数）
cs418-matrix = uniformMatrix 需要 16 个数，却有 { $found } 个
cs418-count = { $keyword }：数量 { $count } 不是 3 的倍数
cs418-texture-name = texture 需要文件名
cs418-texture = 纹理“{ $name }”：{ $why }
cs418-no-png = 没有“png WIDTH HEIGHT FILE”行：这是 CS 418 的文件吗？
cs418-png-words = png 需要 WIDTH HEIGHT FILE，却有 { $found } 个词
cs418-png-side = png：{ $what }“{ $word }”须为 1 到 { $max } 的整数
cs418-png-file = png：“{ $file }”须为不带文件夹的简单文件名
cs418-not-a-number = { $keyword }：“{ $word }”不是数
cs418-integers = { $keyword } 需要 { $count } 个整数，却有 { $found } 个
cs418-not-a-whole-number = { $keyword }：“{ $word }”不是 ≥ 0 的整数
cs418-sized = { $keyword } 需要先给大小再给数
cs418-size-word = { $keyword }：大小“{ $size }”不是整数
cs418-size-zero = { $keyword }：大小不能为 0
cs418-vertices = { $keyword } { $size }：{ $numbers } 个数不是整数个顶点（{ $whole } 个，余 { $left }）
cs418-vertex-index = 读取顶点 { $index }，但“position”只有 { $count } 个顶点
cs418-texture-missing = 题目旁没有这个文件
cs418-texture-unreadable = 无法读取（{ $reason }）
cs418-image-size = 图像为 { $width } × { $height }，题目画的是 { $case_width } × { $case_height }
png-not-an-image = 不是 PNG 图像（{ $reason }）
png-too-large = PNG 太大
png-broken = 损坏的 PNG 图像（{ $reason }）
png-colour-type = 意外的 PNG 颜色类型 { $kind }
buet-size = “{ $word }”不是 1 到 { $max } 的光栅尺寸
buet-config-empty = 为空；需要光栅尺寸“W H”
buet-config-first = 第一行须为光栅尺寸“W H”
buet-one-number = 应为一个数
buet-z-range = 应为“z_front z_rear”
buet-window-negative = left_x 和 bottom_y 须为负数（窗口为 left_x … −left_x）
buet-z-order = z_front 不能大于 z_rear
buet-config-lines = 有 { $count } 个非空行；应为 1 个（“W H”）或 4 个（“W H”、left_x、bottom_y、“z_front z_rear”）
buet-ends = 在应出现{ $what }处结束
buet-numbers = 应为{ $what }（{ $count } 个数），却是“{ $found }”
buet-what-eye = 眼睛位置
buet-what-look = 注视点
buet-what-up = 向上方向
buet-what-perspective = fovY aspect near far
buet-what-vertex = 三角形顶点
buet-what-translation = 平移量
buet-what-scale = 缩放系数
buet-what-rotation = 角度和旋转轴
buet-pop = pop 没有对应的 push
buet-three-coordinates = 应为三个坐标，却是“{ $found }”
buet-triangles = 有 { $count } 个点，不是整数个三角形
cs418-width = 宽度
cs418-height = 高度

rules-describe = 规则 { $preset }：{ $rows }；{ $columns }；{ $store }
rules-rows-half-open = 行半开（min ≤ y < max），交点两两配对
rules-rows-closed = 行闭合（min ≤ y ≤ max），从最小交点到最大交点为一段
rules-rows-top-left = 行取上左（min < y ≤ max：上边上的中心算入，下边上的不算），交点两两配对
rules-columns-centre-inside = 中心在段内的列
rules-columns-cell-holds = 从含 x_a 的单元到含 x_b 的单元的列
rules-columns-half-open = 中心在 [x_l, x_r) 内的列：左边上的中心算入，右边上的不算
rules-store-quantized = 深度四舍五入（半数进位）并饱和
rules-store-exact = 深度精确保存

place-vertex-on-scanline = 多边形 { $polygon }：顶点 { $vertex } ({ $x }, { $y }) 位于第 { $row } 行的扫描线上
place-centre-on-edge = 像素 ({ $x }, { $y })：其中心位于多边形 { $polygon } 的一条边上
place-spans = 多边形 { $polygon }：第 { $row } 行有 { $spans } 段
place-half-depth = 像素 ({ $x }, { $y })，多边形 { $polygon }：z = { $z } 进位为 { $stored }
place-saturation = 像素 ({ $x }, { $y })，多边形 { $polygon }：z = { $z } 舍入为 { $rounded }，保存为 { $stored }
place-hidden = 像素 ({ $x }, { $y })，多边形 { $polygon }：z = { $z } 未通过与已存 { $stored } 的测试
place-intersecting = 多边形 { $first } 和 { $second }：各自在某处位于对方之前

cs418-elements-range = drawElementsTriangles { $count } { $offset } 读取元素 { $offset }…{ $last }，但“elements”只有 { $has } 个
cs418-point-size-range = drawArraysPoints 读取点大小 { $index }，但“pointsize”只有 { $has } 个
cs418-texcoord-range = 顶点 { $index } 带纹理绘制，但“texcoord”只有 { $has } 个顶点
cs418-too-far = 一个顶点落在图像上的 ({ $x }, { $y })，离图像太远无法光栅化（超过 { $reach } 个图像大小）：请打开“frustum”以裁剪它
cs418-too-many-primitives = { $count } 个图元超出 32 位帧缓冲

file-written = 已写入 { $path }
buet-run-summary = { $path }：{ $width }×{ $height } 上 { $triangles } 个三角形，测试了 { $tested } 个像素中心，写入 { $written } 个
buet-answer-not-a-number = 第 { $line } 行第 { $value } 个值：“{ $text }”不是数
buet-answer-rows = { $rows } 行；光栅有 { $height } 行
buet-none = （无）
buet-check-matches = { $answer }：每一行都与 { $path } 的 z 缓冲一致
buet-header-line = 行
buet-header-value = 值
buet-header-answer = 答案
buet-header-right = 正确
buet-header-why = 原因
buet-cell = 单元 ({ $x }, { $y })：{ $why }
buet-extra-value = zsim 在这一行写的值更少：答案多了一个
buet-check-differs = { $answer }：有 { $count } 个值与 { $path } 的 z 缓冲不同
cs418-primitive-point = 顶点 { $vertices } 的点（第 { $line } 行）
cs418-primitive-triangle = 顶点 { $vertices } 的三角形（第 { $line } 行）
cs418-run-summary = { $path }：{ $width } × { $height }，{ $arithmetic } 算术{ $features }：已写入 { $written }
cs418-compare-same = { $path }：每个像素的每个通道都在 { $tolerance } 以内（最大差 { $largest }）
cs418-compare-differs = { $path }：{ $count } 个像素相差超过 { $tolerance }（最大差 { $largest }）：
cs418-compare-pixel = ({ $x }, { $y })：zsim { $ours }，图像 { $theirs }
cs418-compare-more = … 另有 { $count } 个
cs418-arith-alike = 课程的 f64 算术与精确算术对每个采样的绘制都相同
cs418-arith-disagree = 课程的 f64 算术与精确算术不一致的采样有 { $count } 个：
cs418-place-sample = 像素 ({ $px }, { $py }) 的采样 ({ $x }, { $y })
cs418-place-pixel = 像素 ({ $x }, { $y })
cs418-no-span = 无段
cs418-inside = 在内
cs418-outside = 在外
cs418-why-span = { $primitive }：第 { $row } 行其段在 f64 中为 { $course }，精确为 { $exact }，故 x = { $x } 在 f64 中{ $course_side }，精确地{ $exact_side }
cs418-nothing = 无
cs418-why-depth = 两种算术用相同的图元覆盖它，但深度测试在 f64 中保留 { $course }，精确地保留 { $exact }（深度相等，或在舍入误差内）
file-written-in = 已在 { $path } 写入 { $files }
exercise-notes-settings = 练习：种子 { $seed }，{ $width }×{ $height } 光栅，{ $polygons } 个多边形，帧缓冲 { $frame_bits } 位，z 缓冲 { $depth_bits } 位（0 … { $max }），深度测试 { $test }
exercise-notes-asked = 要求：{ $asked }（种子序列中的第 { $candidate } 个候选）
exercise-notes-no-case = 无特定情形
exercise-notes-contains = 包含（在运行轨迹中找到，各取第一处）：
exercise-notes-none = 没有难点情形
exercise-notes-next = 检查答案：zsim check { $path } --frame FRAME.txt --depth DEPTH.txt；给全班评分：zsim grade { $path } CLASS_DIR
png-no-fonts = 此系统没有字体，文字会缺失；请写成 SVG（-o FILE.svg）
png-figure-too-large = 图太大
error-output = 无法写出输出：{ $reason }
memory-header-buffer = 缓冲
memory-header-cells = 单元数
memory-header-bits-per-cell = 每单元位数
memory-header-bits = 位数
memory-header-bytes = 字节数
memory-total = 合计
memory-at-sample = 采样
memory-at-pixel = 像素
memory-supersampled = ，{ $k }×{ $k } 超采样，深度存于每个{ $at }
memory-heading = { $width }×{ $height } 像素，帧缓冲 { $frame_bits } 位，z 缓冲 { $depth_bits } 位{ $sampling }
memory-total-line = 合计：{ $total } 字节 = { $megabytes }
step-antialias-note = 注意：此场景要求 { $k }×{ $k } 超采样；step 显示的是超采样和平均之前每个像素中心的基本覆盖和深度（`zsim run` 显示平均后的缓冲，`zsim explain --pixel X,Y` 显示每个像素的采样）
step-fixed = 在 fixed:{ $bits } 算术中，顶点先对齐到 1/{ $unit } 的倍数，再对对齐后的多边形运行这些精确规则（`zsim run --arith fixed:{ $bits }` 显示结果）
step-float-exact = 精确值 { $z }
step-float-not-exact = 精确算术不覆盖它
step-float-edges = 在包围盒第 { $first } … { $last } 列中心处的边函数
step-float-no-crossings = 无交点
step-float-crossings = 交点 { $crossings }
step-float-heading = { $arith } 算术中：{ $found }
step-float-no-pixel = 没有覆盖任何像素
step-float-missed = 漏掉了精确中心 x = { $columns }
run-summary = { $path }：{ $polygons } 个多边形，测试了 { $tested } 个像素中心，写入 { $written } 个；效果：{ $effects }；阶段：{ $stages }；读取 { $read } ms，光栅化 { $raster } ms，{ $threads } 个线程（{ $rate } M 像素/秒）；内存：缓冲 { $buffers }，场景 { $scene }{ $peak }
run-summary-peak = ，常驻内存峰值 { $peak }
run-summary-peak-ratio = ，常驻内存峰值 { $peak }（{ $ratio }× 缓冲 + 场景）
run-summary-no-effects = 无
run-summary-arith = ；算术 { $arith }
run-arith-compared = 算术：{ $arith }；与精确算术相比，帧缓冲有 { $frame } 个单元不同，z 缓冲有 { $depth } 个单元不同
run-frame-after-all = 所有多边形之后的帧缓冲：
run-depth-after-all = 所有多边形之后的 z 缓冲：
compare-rules-this = 本场景的{ $rules }
compare-rules-other = 对比{ $rules }
compare-rules-same = 每个像素结果相同：没有中心正好落在规则不同的边上
compare-rules-differ = 有 { $count } 个像素不同：
compare-rules-nothing = 无
compare-rules-cell = ({ $x }, { $y })：{ $before } → { $after }；在{ $rules }下被 { $covering } 覆盖，在{ $other_rules }下被 { $other_covering } 覆盖
compare-rules-vertex = 中心 ({ $x }.5, { $y }.5) 是“{ $name }”的顶点 { $vertex }：由交于此处的边决定，各规则集如同在其自身边上
compare-rules-edge = 中心 ({ $x }.5, { $y }.5) 位于“{ $name }”从 { $from } 到 { $to } 的{ $boundary }上：在{ $rules }下{ $verdict }，在{ $other_rules }下{ $other_verdict }
compare-rules-covered = 被覆盖
compare-rules-left-out = 未覆盖
preset-rogers = 教材规则
preset-buet = BUET 规则
preset-gl = OpenGL 规则
preset-vulkan = Vulkan 和 Direct3D 的上左规则
variant-identical = 与基本 z 缓冲的结果相同（帧缓冲和 z 缓冲）
variant-differs = 与基本 z 缓冲相比有 { $count } 个单元不同
variant-result = 结果：{ $result }
segments-kind = 分段：{ $count } 段（{ $segments }），每个多边形归入其包围盒所触及的分段
segments-memory = z 缓冲内存：{ $cells } 个单元 × { $bits } 位 = { $total } 位（整个光栅：{ $whole_cells } 个单元，{ $whole_bits } 位）
segments-visits = 多边形访问次数：{ $visits }（整个光栅：{ $whole }）
pixel-order-ray = 射线法（顶点规则左开右闭；边界上算在内）
pixel-order-arc = 弧长法（象限表；边界上算在内）
pixel-order-heading = 顺序：对每个像素、对每个多边形，一个深度变量（中文课程讲义）；内点测试：{ $test }
pixel-order-header-polygon = 多边形
pixel-order-header-why = 内点测试为何不同
pixel-order-on-boundary = 中心正好在边界上：弧长法算在内，而半区间规则不包括上边和顶点（边只在其下端算）
pixel-order-winding = 多边形绕中心 { $winding } 圈：弧长法把非零环绕数算在内，配对交点（奇偶）算在外
pixel-order-disagree = 弧长法与扫描线规则不一致的中心有 { $count } 个：
antialias-at-sample = 采样
antialias-at-centre = 像素中心
antialias-heading = 抗锯齿：每像素 { $k }×{ $k } 个采样，深度存于每个{ $at }；值为各采样的平均（{ $samples } 分之几）
antialias-frame-after = { $polygon } 之后的帧缓冲（平均）：
antialias-depth-after = { $polygon } 之后的 z 缓冲（平均）：
transparency-all-match = 透明：每个单元都与正确的由后往前混合一致
transparency-header-drawn = 绘制结果
transparency-header-back-to-front = 由后往前
transparency-header-polygons = 此处的多边形，由后往前
transparency-differs = 透明：有 { $count } 个单元与正确的由后往前混合不同（按错误顺序绘制的局部误差：透明多边形后面的多边形若在其后绘制，会通不过深度测试）：
accuracy-header-mode = 模式
accuracy-header-ns = 每像素纳秒
accuracy-header-pixels = 像素数
accuracy-header-frame = 帧单元 ≠ 精确
accuracy-header-depth = 深度单元 ≠ 精确
accuracy-header-worst = 最大深度误差（级）
accuracy-header-time = 相对精确的耗时
accuracy-header-bits = 深度位数
accuracy-header-fighting = z 冲突单元
accuracy-header-memory = z 缓冲内存（字节）
accuracy-header-ms = 时间（ms）
accuracy-set = 精度测试集：{ $width }×{ $height } 上 { $scenes } 个场景（顶点在 1/256 网格上的 4、16、64、256 像素随机三角形，种子 { $seed }，外加 4 个难点情形）；各模式轮流运行 5 轮，时间取各模式的最小值
accuracy-sweep = 两个沿 x = y 相交的近乎共面的平面（世界深度 0 … 1 乘以 2^bits 级；每像素斜率为范围的 1/2^20），{ $cells } 个单元：
progress-bands = 条图块带
progress-polygons = 个多边形

# Inputs zsim refuses before reading.
error-not-regular = { $path }: 不是普通文件（它是{ $kind }）：zsim 只读取普通文件
error-too-large = { $path }: 超出 zsim 读取的上限（{ $limit } MiB）
file-kind-directory = 文件夹
file-kind-fifo = 命名管道（FIFO）
file-kind-device = 设备
file-kind-socket = 套接字
file-kind-link = 符号链接（不跟随）
file-kind-other = 非普通文件
error-not-utf8 = 不是 UTF-8 文本
usage-output-is-input = { $path } 是 zsim 读取的输入之一：请把输出写到别处
usage-output-would-replace = { $path } 中已有 { $files }{ $more ->
    [0] {""}
   *[other] { " " }另有 { $more } 个
}：zsim 不替换任何文件；请选择新的或空的文件夹
usage-tile-zero = --tile 取 1 个像素或以上（0 什么也画不出）
stdout-closed = 标准输出已关闭
buet-look-at-eye = 注视点与眼睛位置相同：视线没有方向
buet-up-along-view = 向上方向为零或与视线方向共线：相机没有朝向
buet-perspective = fovY 和 fovY·aspect 须在 0 到 180 度之间，aspect 和 near 须为正，far 须不同于 near
buet-rotation-axis = 绕轴 0 0 0 的旋转没有方向
token-cut = { $shown }…（{ $count } 个字符）

# The machine's OpenGL.
gpu-no-library = 未找到 OpenGL：{ $reason }（请安装 libegl1 libegl-mesa0 libgl1-mesa-dri）
gpu-refused = OpenGL 拒绝了 { $step }：{ $reason }
gpu-heading = { $path } 由 { $renderer } 绘制，与 zsim 按场景规则和 { $preset } 预设并列
gpu-same = GPU 与 zsim 在每个像素显示同一个多边形
gpu-differ = 有 { $count } 个像素显示了另一个多边形：
gpu-cell = ({ $x }, { $y })：GPU 显示 { $gpu }；zsim 按场景规则显示 { $book }，按 { $preset } 显示 { $covered }
gpu-background = 无
gpu-exact-depth = { $polygon }，精确深度 { $depth }
gpu-why-depth = GPU 为 { $shown } 存储的深度为 { $gpu }（f32 插值，24 位保存）；按场景规则保留的是 { $book }
gpu-not-convex = 注意：{ $polygon } 不是凸的：GPU 从其第一个顶点以三角形扇绘制，这并不是该多边形
speed-header = { $scene }：{ $triangles } 个三角形（{ $polygons } 个多边形的扇形{ $skipped ->
    [0] {""}
   *[other] ；另有 { $skipped } 个多边形不绘制任何像素：退化、侧对、被剔除或在视野之外
  }），测试了 { $pixels } 个像素中心；zsim 用 { $threads } 个线程，{ $tile ->
    [0] 逐个多边形
   *[other] 以 { $tile } 像素见方的图块
}，对比 { $renderer }（LP_NUM_THREADS={ $lp }），交替计时 { $pairs } 对（各先不计时运行一次）
speed-result = zsim { $zsim } 毫秒，GPU { $gpu } 毫秒（中位数）：zsim 用时是 GPU 的 { $ratio } 倍（各对从 { $low } 倍到 { $high } 倍）
speed-fresh = zsim 整次运行（像 `zsim run` 一样使用新缓冲区）：{ $fresh } 毫秒（中位数），是 GPU 时间的 { $ratio }×
speed-memory = zsim 每秒测试 { $rate } 百万个像素中心；复制缓冲区的 { $megabytes } MB 用时 { $copy } 毫秒（{ $bandwidth } GB/s），按每像素 { $bytes } 字节各读写一次计算，每秒最多 { $limit } 百万像素
usage-compare-gpu-plain = --compare-gpu 比较的是基本算法：此场景要求逐像素效果或抗锯齿
usage-no-gpu = --compare-gpu：{ $reason }
gpu-why-depth-unread = GPU 显示 { $shown }；按场景规则保留的是 { $book }（由深度决定：GPU 以 f32 插值）
gpu-no-vulkan = 未找到 Vulkan 设备：{ $reason }（请安装 mesa-vulkan-drivers）
gpu-not-built = 此 zsim 构建时未含 { $feature } 功能：请用 `cargo install --path . --features { $feature }` 构建

## What the system and the JSON reader say (words/system.rs)
io-not-found = 没有这个文件或文件夹
io-permission-denied = 没有权限
io-already-exists = 已经存在
io-is-a-directory = 这是一个文件夹
io-not-a-directory = 路径的一部分不是文件夹
io-storage-full = 磁盘已满
io-read-only = 文件系统是只读的
io-not-utf8 = 文件不是 UTF-8 文本
json-at = { $message }（第 { $line } 行，第 { $column } 列）
json-invalid-type = 类型错误：应为{ $expected }，实际是{ $found }
json-invalid-value = 值错误：应为{ $expected }，实际是{ $found }
json-invalid-length = 有 { $length } 个元素，应为{ $expected }
json-missing-field = 缺少字段 { $field }
json-unknown-field = 未知字段 { $field }；允许的字段：{ $known }
json-unknown-field-none = 未知字段 { $field }
json-unknown-variant = 未知的值 { $variant }；允许的值：{ $known }
json-duplicate-field = 字段 { $field } 出现了两次
json-eof = 文件在一个值的中间结束
json-expected-token = 此处应为 { $token }
json-expected-value = 此处应为一个值
json-trailing = 场景结束后还有文本
json-trailing-comma = 右括号前多了一个逗号
json-key-string = 键必须是带引号的字符串
json-invalid-number = 数字无效
json-number-range = 数字超出范围
json-invalid-escape = 字符串中的转义无效
json-too-deep = 嵌套太深
json-control = 字符串中有控制字符
json-found-integer = 整数 { $value }
json-found-decimal = 小数 { $value }
json-found-string = 字符串 { $value }
json-found-bool = { $value }
json-found-null = null
json-found-list = 列表
json-found-object = 对象
json-want-list = 列表
json-want-string = 字符串
json-want-bool = true 或 false
json-want-number = 数字（或写有分数或小数的字符串）
json-want-vertex = 顶点 [x, y, z]（或裁剪空间中的 [x, y, z, w]）
json-want-object = 对象
json-want-whole = 整数
usage-pixel-not-xy = “{ $text }”不是 X,Y（例如 20,15）
usage-pixel-coordinate = “{ $text }”不是像素坐标
usage-arith = “{ $text }”不是算术模式：`exact`、`f64`、`f64-incremental`、`f32-incremental`、`f32`、`f32-edge` 或 `fixed:K`（K 为 0 到 24）
usage-missing = 缺少：{ $args }
usage-invalid-value = “{ $value }” 不是 { $arg } 的有效值：{ $reason }
usage-unknown-argument = 未知选项 { $arg }
usage-unknown-command = 未知命令 { $name }
usage-conflict = { $arg } 不能与 { $other } 同时使用
usage-see-help = 帮助：zsim --help

## The misconception behind a wrong answer (teach/diagnose.rs)
diagnosis = 可能的原因：{ $what }（解释了 { $wrong } 个错误单元中的 { $explained } 个）
misconception-truncated = 深度被截断（向下取整），而不是四舍五入到最接近的整数
misconception-half-down = 0.5 向下舍入而不是向上（10.5 存为 10）
misconception-rounded-compared = 与 z 缓冲器比较的是舍入后的深度，而不是精确的 z
misconception-no-saturation = 超出 z 缓冲器范围的深度回绕了，而不是饱和
misconception-not-strict = 相等的深度也通过了（≥ 而不是 >）
misconception-reversed = 深度测试反了（把较小的 z 当作更近）
misconception-last-only = 只画了最后一个多边形
misconception-one-early = 答的是前一个多边形之后的状态
misconception-bottom-first = 行从最下面一行开始写
misconception-corners = 在像素角点而不是中心采样
misconception-cell-rule = 列按区段端点所在的单元格取，而不是按区段内的中心
grade-column-cause = 可能的原因
grade-cause = { $what }（{ $wrong } 个中的 { $explained } 个）
grade-causes = 全班可能的原因：
grade-cause-count = { $what }：{ $students } 名学生中有 { $count } 名
answer-more-problems = { "" } · 另有 { $count } 处问题
usage-no-submission = { $folder }：这里没有答案：frame.txt、depth.txt、after-N.frame.txt 或 after-N.depth.txt
gradescope-test = { $after } 之后的{ $buffer }
usage-identity-column = --identity：该平台不按“{ $column }”列导入（Moodle：email、idnumber、username；Canvas：id、sis-user-id、sis-login-id）
usage-no-points = --points 至少为 1
figures-not-built = 这个 zsim 构建时没有 { $format } 图形（figures 功能，默认构建不开启）：请用 `cargo install --path . --features figures` 构建；Debian 软件包包含它。SVG 和 TeX 图形不需要它

## tinyrenderer's OBJ files (courses/tinyrenderer.rs)
obj-vertex-count = 顶点需要 x、y 和 z；这一行有 { $count } 个数
obj-not-a-number = “{ $token }”不是数字
obj-face-corners = 课程中的面有 3 个顶点；这个面有 { $count } 个
obj-bad-index = “{ $token }”不是顶点编号（从 1 开始）
obj-too-many-faces = 面多于 { $max } 个
obj-no-vertex = 顶点 { $index } 不存在：文件中只有 { $count } 个
rules-store-truncated = 深度截断（向下取整）并饱和
rules-sample-corner = ；在整数点 (x, y)（像素角点）采样
rules-compare-level = ；比较的是按存储方式取整后的深度
rules-min-area = ；有向面积小于 { $area } 的多边形被跳过
stage-store-truncated = 存储（截断，饱和到 0…{ $max }）
preset-tinyrenderer = tinyrenderer 的 z 缓冲课程
fate-small-area = 它的有向面积小于规则的界限（背面或细条）：被跳过
heading-small-area = { $start }：平面 { $plane }，被跳过（有向面积小于规则的界限：背面或细条）
tinyrenderer-run = { $model }：{ $faces } 个面，跳过 { $skipped } 个（面积小于 1），绘制 { $drawn } 个；已在 { $folder } 写入 zbuffer.tga 和 framebuffer.tga
tinyrenderer-differ = 精确算术在 { $count } 个像素上得到与课程 f64 不同的 z 缓冲级别
tinyrenderer-differ-pixel = ({ $x }, { $y })，面 { $face }：f64 { $float }，精确 { $exact }（插值的 z 是整数；f64 略小于它，截断后少了一级）
tinyrenderer-line = 第 { $line } 行
explain-others = 另有 { $count } 个多边形到不了这个像素的扫描线：{ $skipped } 个根本不画（被跳过、剔除或侧对），{ $off } 个的行在别处
explain-corner-sample = 规则在整数点 ({ $x }, { $y }) 采样：zsim 把场景平移 ½ 来画，使这个中心就是那个点，下面的坐标是平移后的
stored-truncated = 存入 { $stored }（{ $value } 截断为 { $stored }）
stored-truncated-saturated = 存入 { $stored }（{ $value } 截断并饱和到 { $stored }）
usage-tinyrenderer-size = “{ $text }”不是图像边长：{ $min } … { $max } 像素
quiz-frame-hint = 请输入帧缓冲器将保存的值，不写入则输入 -（q 结束测验）
quiz-frame-does-not-fit = { $text } 放不进这个帧缓冲器：它的单元只存 0 … { $max } 的整数；请重新输入
usage-not-a-preset = “{ $text }” 不是规则预设：请用 rogers、buet、gl、vulkan（d3d、webgpu）或 tinyrenderer
error-outside-folder = { $path }：文件内的名称必须留在该文件所在的文件夹（{ $folder }）内：不能有“..”，不能是绝对路径
usage-output-name-too-long = { $path }：名称超过文件系统允许的长度（{ $max } 字节）；未写入任何文件
usage-output-twice = 同一命令会两次写入 { $path }；未写入任何文件
png-declares-too-many-pixels = 该 PNG 声明了 { $width } × { $height } 个像素，超过 zsim 解码的上限（{ $max }）
cs418-too-many-samples = fsaa { $level } 需要 { $samples } 个采样，超过 zsim 绘制的上限（{ $max }）：请降低 fsaa 或图像尺寸
usage-same-answer-twice = { $path }：{ $files } 回答的是同一状态的同一缓冲区：只交一个
expect-not-states = “{ $text }”不是状态列表：请写 final、each，或用逗号分隔、从 1 开始的多边形编号（1,3）
gradescope-missing = 没有文件回答这一项：请提交 { $file }
gradescope-score-rule = 得分：场景改变的 { $changed } 个单元中答对的比例（{ $right } 个），每有一个单元在缓冲区应保持初始值处被写入（共 { $stray } 个）就减去同样一份；未作答的单元不计
gradescope-ambiguous = { $files } 都回答这一项：均不评分；只交一个
gradescope-unused = 未评分（作业不要求这些文件）：{ $files }
usage-same-student-twice = { $path }：{ $files } 显示出来都是“{ $student }”：请重命名其中一个；未评分
usage-gradebook-cannot-tell = 对成绩册而言“{ $first }”和“{ $second }”是同一个学生（同一单元格，不区分大小写）：请重命名其中一个；未写入任何内容
png-figure-too-many-pixels = 按该 --scale，PNG 将超过 { $max } 个像素：请调小
check-more-cells = …… 另有 { $count } 个单元格不同，未列出

grade-skipped = 未评分：{ $file } 不是答案文件（应为 姓名.frame.txt 或 姓名.depth.txt）
grade-skipped-near = 未评分：{ $file } 看起来是 { $student } 的{ $buffer }：请命名为 { $name }

## The browser playground
play-title = zsim 演练场：逐步演示 z 缓冲
play-intro = 编辑场景；下面的每个缓冲都由编译到浏览器中的 zsim 库绘制。
play-language = 语言
play-scene = 场景
play-width = 宽度
play-height = 高度
play-frame-bits = 帧缓冲位数
play-depth-bits = z 缓冲位数
play-depth-test = 深度测试
play-preset = 规则
play-preset-none = 教材的规则
play-snap = 网格步长
play-polygon = 多边形
play-value = 值
play-add-polygon = + 多边形
play-remove-polygon = − 多边形
play-add-vertex = + 顶点
play-remove-vertex = − 顶点
play-json = 场景 JSON
play-share = 复制此场景的链接
play-shared = 链接已在地址栏中：请从那里复制。
play-buffers = 每个多边形之后的缓冲
play-final = 最终缓冲（与 zsim run --final 的输出相同）
play-grid = 光栅
play-grid-help = 拖动顶点可移动它；单击像素可查看其历史。
play-explain = 像素的历史
play-stepper = 逐条扫描线
play-figure = 图
play-homework = 检查作业答案
play-homework-help = 按教材的格式输入或粘贴矩阵，从最上面一行开始。
play-check = 检查
play-answer-grid = 在网格中输入（从清空的缓冲开始）
play-after = 之后
play-your-answer = 你的答案
play-too-large = 此场景太大，无法逐格显示（超过 { $cells } 个像素或 { $polygons } 个多边形）：只显示最终缓冲。
play-not-printed = 此光栅超过 { $cells } 个像素：缓冲已绘制，但不在此打印；请用 zsim run --final 打印。
play-no-antialias = 本页绘制场景时不做反走样；反走样的图像请用 zsim run 查看。
play-no-polygon = 场景中没有这个多边形。
play-not-json = 场景不是 JSON：{ $reason }
play-bad-edit = 此修改不适用于该场景的 JSON。
play-bad-address = 地址中没有场景：#scene= 之后应是 base64url 编码的场景 JSON。

## The lesson (teach::lesson): the same in every front end.
lesson-key-next = 下一条扫描线
lesson-key-back = 后退
lesson-key-next-polygon = 下一个多边形
lesson-key-previous-polygon = 上一个多边形
lesson-key-skip = 跳过本扫描线的问题
lesson-key-quit = 退出
lesson-keys = 按键：{ $keys }，g Y 转到扫描线 Y；按 Enter 检查答案
lesson-hint-misconception = 看起来{ $what }
lesson-hint-is-written = 该像素通过了深度测试：请再次比较它的精确 z 与存储值
lesson-hint-is-not-written = 该像素没有通过深度测试：请再次比较它的精确 z 与存储值
lesson-hint-centre-on-boundary = 有一个中心恰好位于多边形边界上：由哪条规则决定？
lesson-hint-column-outside = 你算入了中心位于区间之外的列
lesson-hint-column-left-out = 你漏掉了中心位于区间之内的列
lesson-hint-other = 用平面方程计算像素中心的 z，与存储值比较，然后取整
lesson-right = { $said }：正确。{ $why }
lesson-right-second = { $said }：第二次尝试正确。{ $why }
lesson-try-again = { $said }：还不对：{ $hint }（再试一次）
lesson-revealed = { $said }：又错了。答案是 { $expected }：{ $why }
lesson-skipped = 已跳过 { $count } 个问题（计为未回答）
lesson-score = 测验：首次答对 { $first }，第二次答对 { $second }，显示答案 { $revealed }，跳过 { $skipped }，共 { $asked } 题
lesson-ask-coverage = { $polygon }，扫描线 { $scanline }：它覆盖哪些列的中心？（按 首列-末列 输入，例如 3-7，若没有则输入 -）
lesson-ask-depth = 像素 ({ $x }, { $y })，存储值 { $stored }：之后 z 缓冲区的值？（一个值，若未写入则输入 -）
lesson-ask-frame = 像素 ({ $x }, { $y })，帧缓冲区 { $before }：之后帧缓冲区的值？（一个值，若未写入则输入 -）
lesson-last-try = 最后一次尝试：{ $ask }
lesson-questions-open = 本扫描线还有 { $open } 个未答问题：请先回答，或按 s 跳过
lesson-no-such-polygon = 没有多边形 { $polygon }：场景中共有 { $count } 个
page-no-quiz = 本页只展示步骤，不提问：测验在浏览器演练场中（当 zsim 构建时包含它，本命令会写出该页面；见指南中“浏览器演练场”一章）以及 zsim step --quiz 中。
play-scene-name = 场景
page-skip = 跳过 (s)
play-quiz-kind = 测验的内容
play-coverage-kind = 覆盖的列，然后是 z 缓冲区
play-examples = 示例
play-reset = 重置
play-copied = 链接已复制。
play-grid-label = 光栅：方向键移动像素光标，Enter 解释该像素
play-buffer-kind = 哪个缓冲区
play-example-rogers = 书中的示例
play-example-section = 书中的截面
play-example-less = 深度测试“小于”
play-example-cull = 剔除背面
play-example-concave = 凹多边形
play-legend = 帧缓冲区的值：
play-hidden = 还有 { $count } 个被覆盖的像素，逐个提问
play-legend-value = { $value }
lesson-said-meant = { $said }（{ $meant }）
play-error-line = 第 { $line } 行：{ $text }
answer-empty = 文件为空：其中没有答案的任何一行
answer-decimal-comma = 第 { $line } 行：{ $text } 含有小数逗号；每个单元格是一个整数（单元格之间用空格分隔）
usage-answer-without-buffer = { $path } 是一个答案：请用 --frame { $path } 或 --depth { $path } 指定
grade-mistakes-more = 另有 { $count } 个两名或更多学生答错的单元格未列出
check-hint-other-buffer = 这正是{ $other }，而不是{ $buffer }：是否把它当作另一个缓冲区交上来了？
play-scene-too-long = 该场景有 { $bytes } 字节；本页面只读取不超过 { $max } 字节的场景：请用 zsim run 绘制。
lesson-nothing-to-skip = 这里没有未答的问题：无需跳过
