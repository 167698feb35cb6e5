# zsim's words in Chinese: drawing a scene: run's reports, the stages, headings, rules and presets, effects, explain, figures, the GPU and speed.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
depth-test-greater = 大于
depth-test-less = 小于
depth-test-greater-equal = 大于等于
depth-test-less-equal = 小于等于
depth-test-always = 总是
depth-test-never = 从不
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
heading-polygon-scanline = { " " }{ $polygon }，扫描线 { $scanline }
heading-end-of-scene = { " 场景结束" }
end-of-scene = 场景结束
span-line = 区段 { $n }：{ $left } … { $right }；{ $columns }
span-no-centre = 不含任何像素中心
test-passes-uncompared = { $test } 通过，
test-not = { "不满足 " }
outcome-hidden-short = 被遮挡
depth-steps-from = { "，从 " }{ $start } 起走了 { $count } 步 −a/c
meant-not-written = 不写入
meant-value-written = 写入的值
meant-value-kept = 不写入：保持原值
meant-value = 一个值
frame-after-scanline = 本扫描线之后的帧缓冲器
depth-after-scanline = 本扫描线之后的z缓冲器
scanline-of-count = 第 { $at } 条扫描线，共 { $count } 条
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
fate-outside-view = 它位于视见体（−w ≤ x, y, z ≤ w）之外：被完全裁剪，不绘制
heading-outside-view = { $start }：位于视见体（−w ≤ x, y, z ≤ w）之外：被完全裁剪，不绘制
heading-view = { "；裁剪空间：" }{ $of } 个顶点中有 { $inside } 个在视见体内，经裁剪、除以 w 和视口变换后按 { $n } 边形绘制
polygon-opacity = 不透明度 { $alpha } 不在 0 … 1 之内
polygon-value-too-wide = 值 { $value } 超出 { $bits } 位帧缓冲器的范围（最大 { $max }）
list-or = { $rest } 或 { $last }
rules-describe = 规则 { $preset }：{ $rows }；{ $columns }；{ $store }
rules-rows-half-open = 行半开（min ≤ y < max），交点两两配对
rules-rows-closed = 行闭合（min ≤ y ≤ max），从最小交点到最大交点为一段
rules-rows-top-left = 行取上左（min < y ≤ max：上边上的中心算入，下边上的不算），交点两两配对
rules-columns-centre-inside = 中心在段内的列
rules-columns-cell-holds = 从含 x_a 的单元到含 x_b 的单元的列
rules-columns-half-open = 中心在 [x_l, x_r) 内的列：左边上的中心算入，右边上的不算
rules-store-quantized = 深度四舍五入（半数进位）并饱和
rules-store-exact = 深度精确保存
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
run-summary = { $path }：{ $polygons } 个多边形，测试了 { $tested } 个像素中心，写入 { $written } 个；效果：{ $effects }；阶段：{ $stages }；读取 { $read } ms{ $made }，光栅化 { $raster } ms，{ $threads } 个线程（{ $rate } M 像素/秒）；内存：缓冲 { $buffers }，场景 { $scene }{ $peak }
run-summary-peak = ，常驻内存峰值 { $peak }
run-summary-peak-ratio = ，常驻内存峰值 { $peak }（{ $ratio }× 缓冲 + 场景）
run-summary-made = ，建立缓冲 { $made } ms
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
speed-fresh = zsim 整次运行，新建缓冲区（即 `zsim run` 的建立缓冲与光栅化合计）：{ $fresh } 毫秒（中位数），是 GPU 时间的 { $ratio }×
speed-memory = zsim 每秒测试 { $rate } 百万个像素中心；复制缓冲区的 { $megabytes } MB 用时 { $copy } 毫秒（{ $bandwidth } GB/s），按每像素 { $bytes } 字节各读写一次计算，每秒最多 { $limit } 百万像素
gpu-why-depth-unread = GPU 显示 { $shown }；按场景规则保留的是 { $book }（由深度决定：GPU 以 f32 插值）
gpu-no-vulkan = 未找到 Vulkan 设备：{ $reason }（请安装 mesa-vulkan-drivers）
gpu-not-built = 此 zsim 构建时未含 { $feature } 功能：请用 `cargo install --path . --features { $feature }` 构建
figures-not-built = 这个 zsim 构建时没有 { $format } 图形（figures 功能，默认构建不开启）：请用 `cargo install --path . --features figures` 构建；Debian 软件包包含它。SVG 和 TeX 图形不需要它
rules-store-truncated = 深度截断（向下取整）并饱和
rules-sample-corner = ；在整数点 (x, y)（像素角点）采样
rules-compare-level = ；比较的是按存储方式取整后的深度
rules-min-area = ；有向面积小于 { $area } 的多边形被跳过
stage-store-truncated = 存储（截断，饱和到 0…{ $max }）
preset-tinyrenderer = tinyrenderer 的 z 缓冲课程
fate-small-area = 它的有向面积小于规则的界限（背面或细条）：被跳过
heading-small-area = { $start }：平面 { $plane }，被跳过（有向面积小于规则的界限：背面或细条）
explain-others = 另有 { $count } 个多边形到不了这个像素的扫描线：{ $skipped } 个根本不画（被跳过、剔除或侧对），{ $off } 个的行在别处
explain-corner-sample = 规则在整数点 ({ $x }, { $y }) 采样：zsim 把场景平移 ½ 来画，使这个中心就是那个点，下面的坐标是平移后的
stored-truncated = 存入 { $stored }（{ $value } 截断为 { $stored }）
stored-truncated-saturated = 存入 { $stored }（{ $value } 截断并饱和到 { $stored }）
heading-scene = 场景
heading-scene-json = 场景 JSON
heading-buffers-each-polygon = 每个多边形之后的缓冲
heading-final-buffers = 最终缓冲（与 zsim run --final 的输出相同）
heading-raster = 光栅
heading-pixel-history = 像素的历史
heading-scanline-by-scanline = 逐条扫描线
heading-figure = 图
heading-homework = 检查作业答案
antialias-not-drawn = 本页绘制场景时不做反走样；反走样的图像请用 zsim run 查看。
heading-examples = 示例
buffer-kind-label = 哪个缓冲区
pixels-hidden-asked = 还有 { $count } 个被覆盖的像素，逐个提问
