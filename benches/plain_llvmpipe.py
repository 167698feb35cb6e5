#!/usr/bin/env python3
"""The plainest OpenGL draw of a zsim scene, to hold `zsim speed`'s harness to.

moderngl over EGL (Mesa's llvmpipe where no GPU is present), one context, no
window: the scene's triangles (each polygon a fan, as zsim gives them to the
GPU) uploaded once as positions and a flat colour, a framebuffer of the
raster's size with a 24-bit depth buffer and the scene's depth test; then, each
round, clear, draw, glFinish, timed. Prints the median and the rounds.

    pip install moderngl
    LP_NUM_THREADS=0 python3 benches/plain_llvmpipe.py SCENE.json [ROUNDS]

LP_NUM_THREADS=0 is what `zsim speed --threads 1` sets (llvmpipe rasterizes on
the thread that draws); leave it unset for llvmpipe's own threads.
"""

import array
import json
import statistics
import sys
import time
from fractions import Fraction

import moderngl


def number(value):
    return float(Fraction(value) if isinstance(value, str) else value)


def main():
    path = sys.argv[1]
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 15
    with open(path) as file:
        scene = json.load(file)
    width, height = scene.get("width", 32), scene.get("height", 32)
    depth_max = (1 << scene.get("depth_bits", 4)) - 1
    test = scene.get("depth_test", "greater")
    data = []
    for index, polygon in enumerate(scene["polygons"]):
        points = [[number(c) for c in vertex] for vertex in polygon["vertices"]]
        colour = [((index + 1) >> shift & 0xFF) / 255.0 for shift in (0, 8, 16)] + [1.0]
        for i in range(1, len(points) - 1):
            for x, y, z in (points[0], points[i], points[i + 1]):
                data += [2 * x / width - 1, 2 * y / height - 1, 2 * z / depth_max - 1] + colour
    gl = moderngl.create_standalone_context(backend="egl", require=330)
    program = gl.program(
        vertex_shader="""#version 330 core
            layout(location = 0) in vec3 position;
            layout(location = 1) in vec4 colour;
            flat out vec4 drawn;
            void main() { gl_Position = vec4(position, 1.0); drawn = colour; }""",
        fragment_shader="""#version 330 core
            flat in vec4 drawn;
            out vec4 shown;
            void main() { shown = drawn; }""",
    )
    buffer = gl.buffer(array.array("f", data).tobytes())
    vao = gl.vertex_array(program, [(buffer, "3f 4f", "position", "colour")])
    framebuffer = gl.framebuffer(
        color_attachments=[gl.renderbuffer((width, height), 4)],
        depth_attachment=gl.depth_renderbuffer((width, height)),
    )
    framebuffer.use()
    gl.enable(moderngl.DEPTH_TEST)
    gl.depth_func = {"greater": ">", "less": "<", "greater-equal": ">=", "less-equal": "<="}[test]
    clear_depth = 0.0 if test.startswith("greater") else 1.0
    gl.finish()

    def draw():
        start = time.perf_counter()
        framebuffer.clear(0.0, 0.0, 0.0, 0.0, depth=clear_depth)
        vao.render(moderngl.TRIANGLES)
        gl.finish()
        return time.perf_counter() - start

    draw()
    times = [draw() for _ in range(rounds)]
    print(
        f"{path}: {len(data) // 21} triangles on {width}x{height}, {gl.info['GL_RENDERER']}: "
        f"clear + draw + finish {statistics.median(times) * 1e3:.2f} ms (median of {rounds}; "
        f"{min(times) * 1e3:.2f} … {max(times) * 1e3:.2f})"
    )


if __name__ == "__main__":
    main()
