# zsim's words in Chinese: stepping and the lesson: the stepper's views and keys, the questions, hints and misconceptions, the page's controls.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
title-stepper = zsim step ·{ $heading } · { $view }{ $score } · ? 按键
score-short = { " · 测验 " }{ $right }/{ $asked }
key-does-nothing = 这个键在这里不起作用：按 ? 查看按键
no-later-polygon = 后面没有覆盖像素的多边形
no-earlier-polygon = 前面没有覆盖像素的多边形
go-to-row-prompt = 转到该行的扫描线：{ $text }▏（Enter 转到，Esc 取消）
keys-summary = n/→ 下一步 · b/← 后退 · p/P 多边形 · g 转到 · f/z 缓冲器 · m 逐像素 · q 退出
no-scanline = 没有扫描线
columns-shown = 显示 x { $first } … { $last }（全部 0 … { $max }）
pixel-table-heading = x { $z } 测试 → 写入值（帧）
keys-pixel-by-pixel = m：逐像素显示，附原因
pixel-centre-depth = ({ $x }, { $y })：中心 x = { $centre }，z = { $z }{ $steps }
keys-heading = { " 按键 " }
keys-help =
    g                  转到某行的扫描线
    f / z              显示帧缓冲器 / z缓冲器
    m                  逐像素 / 逐扫描线
    PgUp PgDn < >      滚动光栅
    { "[ ]" }                滚动表格
    ?                  显示这些按键（按任意键关闭）

    黄色：区段内被覆盖的像素
    青色：本多边形此前写入的像素
quiz-mistakes = 你的错误：
quiz-coverage-hint = 请输入被覆盖的列，格式为 起-止（多段用空格分开：3-5 9-12），没有则输入 -
quiz-coverage-why = 区段为 { $spans }；某列的中心 x + 1/2 落在区段内时，该列被覆盖
quiz-coverage-mistake = { $polygon } 的第 { $row } 行：你的答案是列 { $said }，正确为 { $right }：{ $why }
quiz-depth-hint = 请输入 z缓冲器将保存的值，不写入则输入 -（q 结束测验）
quiz-not-an-answer = “{ $text }”不是答案：{ $hint }
quiz-does-not-fit = { $text } 放不进这个 z 缓冲器：它的单元只存 0 … { $max } 的整数级；请重新输入
quiz-keeps = -（保持 { $value }）
quiz-depth-mistake = { $polygon } 的 ({ $x }, { $y })：你的答案 { $said }，正确为 { $right }：{ $reason }
command-back = ◀ 后退 (b)
command-next = 下一步 ▶ (n)
command-previous-polygon = ◀◀ 多边形 (P)
command-next-polygon = 多边形 ▶▶ (p)
command-show-frame = 帧缓冲器 (f)
command-show-depth = z缓冲器 (z)
quiz-label = 测验
column-stored = 原值
column-depth-after = 之后的 z缓冲器值
column-why = 原因
keeps-value = –（保持 { $value }）
command-check-answers = 检查答案
step-skip-fate = { $polygon }：{ $why }
step-skip-no-scanline = { $polygon }：不到达光栅的任何扫描线
step-skip-no-centre = { $polygon }，扫描线 { $scanline }：没有覆盖任何像素中心
step-skip-no-centre-no-crossings = { $polygon }，扫描线 { $scanline }：没有覆盖任何像素中心（没有交点）
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
pixel-order-ray = 射线法（顶点规则左开右闭；边界上算在内）
pixel-order-arc = 弧长法（象限表；边界上算在内）
pixel-order-heading = 顺序：对每个像素、对每个多边形，一个深度变量（中文课程讲义）；内点测试：{ $test }
pixel-order-header-polygon = 多边形
pixel-order-header-why = 内点测试为何不同
pixel-order-on-boundary = 中心正好在边界上：弧长法算在内，而半区间规则不包括上边和顶点（边只在其下端算）
pixel-order-winding = 多边形绕中心 { $winding } 圈：弧长法把非零环绕数算在内，配对交点（奇偶）算在外
pixel-order-disagree = 弧长法与扫描线规则不一致的中心有 { $count } 个：
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
quiz-frame-hint = 请输入帧缓冲器将保存的值，不写入则输入 -（q 结束测验）
quiz-frame-does-not-fit = { $text } 放不进这个帧缓冲器：它的单元只存 0 … { $max } 的整数；请重新输入
title-scene-editor = zsim 演练场：逐步演示 z 缓冲
intro-scene-editor = 编辑场景；下面的每个缓冲都由编译到浏览器中的 zsim 库绘制。
field-language = 语言
field-width = 宽度
field-height = 高度
field-frame-bits = 帧缓冲位数
field-depth-bits = z 缓冲位数
field-depth-test = 深度测试
field-preset = 规则
field-preset-none = 教材的规则
field-snap = 网格步长
field-polygon = 多边形
field-value = 值
command-add-polygon = + 多边形
command-remove-polygon = − 多边形
command-add-vertex = + 顶点
command-remove-vertex = − 顶点
command-copy-link = 复制此场景的链接
link-in-address-bar = 链接已在地址栏中：请从那里复制。
raster-help = 拖动顶点可移动它；单击像素可查看其历史。
homework-help = 按教材的格式输入或粘贴矩阵，从最上面一行开始。
command-check = 检查
column-after = 之后
column-your-answer = 你的答案
no-such-polygon = 场景中没有这个多边形。
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
lesson-right = { $said }：正确。{ $why }
lesson-right-second = { $said }：第二次尝试正确。{ $why }
lesson-try-again = { $said }：还不对：{ $hint }（再试一次）
lesson-hint-neighbouring-row = 这些是下一行或上一行的列：这条扫描线是 y = 行 + ½
lesson-hint-rounded-up = 看起来你向上取整了：z 缓冲存储最接近的整数（一半向上）
lesson-hint-half-down = 看起来你把一半向下取整了：一半应向上取整
lesson-try-again-plain = { $said }：还不对（再试一次）
lesson-revealed = { $said }：又错了。答案是 { $expected }：{ $why }
lesson-skipped = 已跳过 { $count } 个问题（计为未回答）
lesson-score = 测验：首次答对 { $first }，第二次答对 { $second }，显示答案 { $revealed }，跳过 { $skipped }，共 { $asked } 题
lesson-ask-coverage = { $polygon }，扫描线 { $scanline }：它覆盖哪些列的中心？（按 首列-末列 输入，例如 3-7，若没有则输入 -）
lesson-ask-depth = 像素 ({ $x }, { $y })，存储值 { $stored }：之后 z 缓冲区的值？（一个值，若未写入则输入 -）
lesson-ask-frame = 像素 ({ $x }, { $y })，帧缓冲区 { $before }：之后帧缓冲区的值？（一个值，若未写入则输入 -）
lesson-last-try = 最后一次尝试：{ $ask }
lesson-questions-open = 本扫描线还有 { $open } 个未答问题：请先回答，或按 s 跳过
lesson-no-such-polygon = 没有多边形 { $polygon }：场景中共有 { $count } 个
quiz-not-on-recorded-steps = 本页只展示步骤，不提问：测验在浏览器演练场中（当 zsim 构建时包含它，本命令会写出该页面；见指南中“浏览器演练场”一章）以及 zsim step --quiz 中。
command-skip = 跳过 (s)
command-end-quiz = 结束测验 (q)
quiz-kind-label = 测验的内容
quiz-kind-coverage = 覆盖的列，然后是 z 缓冲区
command-reset = 重置
link-copied = 链接已复制。
raster-label = 光栅：方向键移动像素光标，Enter 解释该像素
example-rogers = 书中的示例
example-section = 书中的截面
example-less = 深度测试“小于”
example-cull = 剔除背面
example-concave = 凹多边形
legend-heading = 帧缓冲区的值：
legend-value = { $value }
lesson-said-meant = { $said }（{ $meant }）
lesson-nothing-to-skip = 这里没有未答的问题：无需跳过
step-line-not-text = 这一行不是文本（UTF-8）：请重新输入
lesson-hidden-until-answered = 在回答或跳过本扫描线的问题之前隐藏
