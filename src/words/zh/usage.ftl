# zsim's words in Chinese: requests that do not fit the command or the scene.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

usage-arith-plain-rules = { $arith } 算术按教材规则模拟基本算法；此场景要求其他规则或逐像素效果，这些由精确算术绘制
usage-arith-greater-or-less = { $arith } 算术只模拟 greater 和 less 两种深度测试；此场景要求 { $test }，它由精确算术绘制
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
usage-not-a-hard-case = “{ $name }”不是难点情形：{ $names }
usage-exercise-size = 练习的每边为 4 … 64 个像素，而不是 { $width }×{ $height }
usage-exercise-polygons = 练习有 1 … 8 个多边形，而不是 { $count }
usage-exercise-bits = 手算练习中帧缓冲器取 1 … 8 位，z缓冲器取 1 … 16 位
usage-exercise-two-polygons = hidden 和 intersecting 需要两个或更多多边形
usage-exercise-not-found = 在 { $tries } 次尝试中没有出现 { $width }×{ $height } 上含 { $polygons } 个多边形且包含全部 { $cases } 的场景；请减少情形、增加多边形或加大光栅
usage-inside-needs-pixel-order = --inside 选择 --order pixels 的点在多边形内测试；请加上 --order pixels
usage-tiles-need-format-none = --tile 和 --threads 只适用于 --format none、--final 和 --after（否则按顺序显示每个多边形画完后的状态）
usage-format-none-is-plain = --format none 汇总 z 缓冲循环；带 --segments、--order pixels 或抗锯齿时请用 text 或 json
usage-no-scanlines = { $polygon } 没有扫描线：{ $why }
usage-scanline-rows = { $reach }：它的行为 { $first } … { $last }
usage-scanline-no-rows = { $reach }：它不到达光栅的任何一行
usage-output-is-input = { $path } 是 zsim 读取的输入之一：请把输出写到别处
usage-output-would-replace = { $path } 中已有 { $files }{ $more ->
    [0] {""}
   *[other] { " " }另有 { $more } 个
}：zsim 不替换任何文件；请选择新的或空的文件夹
usage-tile-zero = --tile 取 1 个像素或以上（0 什么也画不出）
usage-compare-gpu-plain = 与 GPU 比较的是基本算法：此场景要求逐像素效果或抗锯齿
usage-pixel-not-xy = “{ $text }”不是 X,Y（例如 20,15）
usage-pixel-coordinate = “{ $text }”不是像素坐标
usage-arith = “{ $text }”不是算术模式：`exact`、`f64`、`f64-incremental`、`f32-incremental`、`f32`、`f32-edge` 或 `fixed:K`（K 为 0 到 24）
usage-missing = 缺少：{ $args }
usage-invalid-value = “{ $value }” 不是 { $arg } 的有效值：{ $reason }
usage-unknown-argument = 未知选项 { $arg }
usage-unknown-command = 未知命令 { $name }
usage-conflict = { $arg } 不能与 { $other } 同时使用
usage-see-help = 帮助：zsim --help
usage-no-submission = { $folder }：这里没有答案：frame.txt、depth.txt、after-N.frame.txt 或 after-N.depth.txt
usage-identity-column = --identity：该平台不按“{ $column }”列导入（Moodle：email、idnumber、username；Canvas：id、sis-user-id、sis-login-id）
usage-no-points = --points 至少为 1
usage-tinyrenderer-size = “{ $text }”不是图像边长：{ $min } … { $max } 像素
usage-not-a-preset = “{ $text }” 不是规则预设：请用 rogers、buet、gl、vulkan（d3d、webgpu）或 tinyrenderer
segments-form = “{ $text }” 不是 strips:N、tiles:N 或 rows:1（N ≥ 1）
segments-count = “{ $count }” 不是整数
segments-rows = rows 只接受 1（一次一条扫描线）
usage-output-name-too-long = { $path }：名称超过文件系统允许的长度（{ $max } 字节）；未写入任何文件
usage-output-twice = 同一命令会两次写入 { $path }；未写入任何文件
usage-same-answer-twice = { $path }：{ $files } 回答的是同一状态的同一缓冲区：只交一个
grade-left-out-of-import = 未写入成绩册：对成绩册而言“{ $first }”和“{ $second }”是同一个学生（同一单元格，不区分大小写）：请重命名其中一个，再导入他们的行
usage-answer-without-buffer = { $path } 是一个答案：请用 --frame { $path } 或 --depth { $path } 指定
usage-line-too-long = 一行超过 { $max } 字节：课程到此结束，得分见上
usage-html-quiz = --html --quiz 写出演练场页面，其测验按精确算术提问：请去掉 --arith
usage-no-playground = 此 zsim 构建时未包含浏览器演练场：请安装包含它的 Debian 软件包或发布归档，或带上它构建 zsim（先运行 web/build，再 ZSIM_PLAYGROUND=target/web cargo build）
