//! OpenGL through EGL, loaded at run time (see the module above).

use glow::HasContext;
use khronos_egl as egl;

use super::{GpuError, GpuPicture, GpuTriangle};
use crate::raster::depth::DepthTest;

/// An OpenGL context on the machine's EGL, with no window.
pub struct Gl {
    egl: egl::DynamicInstance<egl::EGL1_5>,
    display: egl::Display,
    context: egl::Context,
    gl: glow::Context,
    renderer: String,
}

impl std::fmt::Debug for Gl {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Gl").field("renderer", &self.renderer).finish_non_exhaustive()
    }
}

/// Mesa's platform for contexts without any window system.
const PLATFORM_SURFACELESS_MESA: egl::Enum = 0x31DD;

/// Runs `f` with the process's standard error sent to a temporary file, and
/// returns what was written there; standard error is put back before it
/// returns. Where that cannot be done, `f` runs as it is.
fn captured_stderr<T>(f: impl FnOnce() -> T) -> (T, String) {
    #[cfg(unix)]
    {
        use std::io::{Read, Seek};
        use std::os::fd::AsRawFd;
        if let Ok(mut file) = tempfile::tempfile() {
            // SAFETY: dup and dup2 on descriptor 2 and a file this function owns;
            // descriptor 2 is restored from its duplicate before returning.
            let saved = unsafe { libc::dup(2) };
            if saved >= 0 && unsafe { libc::dup2(file.as_raw_fd(), 2) } >= 0 {
                let result = f();
                // SAFETY: puts the saved descriptor back as 2 and closes the duplicate.
                unsafe {
                    libc::dup2(saved, 2);
                    libc::close(saved);
                }
                let mut said = String::new();
                let _ = file.rewind().and_then(|_| file.take(64 << 10).read_to_string(&mut said));
                return (result, said);
            }
            if saved >= 0 {
                // SAFETY: closes the duplicate made above.
                unsafe { libc::close(saved) };
            }
        }
    }
    (f(), String::new())
}

fn refused(step: &'static str) -> impl Fn(egl::Error) -> GpuError {
    move |error| GpuError::Refused { step, reason: error.to_string() }
}

impl Gl {
    /// Loads `libEGL.so.1` and makes an OpenGL 3.3 core context current on
    /// this thread, with no surface.
    pub fn open() -> Result<Gl, GpuError> {
        // What Mesa prints while it starts (`libEGL warning: …`) is kept
        // from the terminal and told as part of zsim's one line instead.
        let (opened, said) = captured_stderr(Gl::open_quietly);
        opened.map_err(|error| match (error, said.lines().find(|line| !line.trim().is_empty())) {
            (GpuError::Refused { step, reason }, Some(line)) => {
                GpuError::Refused { step, reason: format!("{reason} ({})", crate::words::printable(line.trim())) }
            }
            (GpuError::NoLibrary(reason), Some(line)) => {
                GpuError::NoLibrary(format!("{reason} ({})", crate::words::printable(line.trim())))
            }
            (error, _) => error,
        })
    }

    fn open_quietly() -> Result<Gl, GpuError> {
        // SAFETY: loading the system's EGL runs its initializers, as any program linking it does.
        let egl = unsafe { egl::DynamicInstance::<egl::EGL1_5>::load_required() }
            .map_err(|error| GpuError::NoLibrary(error.to_string()))?;
        // SAFETY: the surfaceless platform takes no native display; the attribute list is terminated.
        let display =
            unsafe { egl.get_platform_display(PLATFORM_SURFACELESS_MESA, egl::DEFAULT_DISPLAY, &[egl::ATTRIB_NONE]) }
                .map_err(refused("eglGetPlatformDisplay"))?;
        egl.initialize(display).map_err(refused("eglInitialize"))?;
        egl.bind_api(egl::OPENGL_API).map_err(refused("eglBindAPI"))?;
        let attributes = [egl::SURFACE_TYPE, egl::PBUFFER_BIT, egl::RENDERABLE_TYPE, egl::OPENGL_BIT, egl::NONE];
        let config = egl
            .choose_first_config(display, &attributes)
            .map_err(refused("eglChooseConfig"))?
            .ok_or(GpuError::Refused { step: "eglChooseConfig", reason: "no OpenGL configuration".into() })?;
        let context_attributes = [
            egl::CONTEXT_MAJOR_VERSION,
            3,
            egl::CONTEXT_MINOR_VERSION,
            3,
            egl::CONTEXT_OPENGL_PROFILE_MASK,
            egl::CONTEXT_OPENGL_CORE_PROFILE_BIT,
            egl::NONE,
        ];
        let context =
            egl.create_context(display, config, None, &context_attributes).map_err(refused("eglCreateContext"))?;
        egl.make_current(display, None, None, Some(context)).map_err(refused("eglMakeCurrent"))?;
        // SAFETY: the context is current on this thread; the loader returns its functions or null.
        let gl = unsafe {
            glow::Context::from_loader_function(|name| {
                egl.get_proc_address(name).map_or(std::ptr::null(), |function| function as *const _)
            })
        };
        // SAFETY: a current context answers queries.
        let renderer = unsafe { gl.get_parameter_string(glow::RENDERER) };
        Ok(Gl { egl, display, context, gl, renderer })
    }

    /// The implementation's name, e.g. `llvmpipe (LLVM 15.0.6, 256 bits)`.
    pub fn renderer(&self) -> &str {
        &self.renderer
    }

    /// Draws `triangles` in order on a `width`×`height` raster. With a
    /// depth test, z (in levels, 0 … `depth_max`) is compared as the test
    /// says, the buffer cleared as zsim clears it; without, the last
    /// triangle covering a pixel shows there.
    pub fn draw(
        &self,
        size: (u32, u32),
        triangles: &[GpuTriangle],
        depth: Option<(DepthTest, u32)>,
    ) -> Result<GpuPicture, GpuError> {
        let drawing = self.upload(size, triangles, depth)?;
        drawing.draw();
        drawing.picture()
    }

    /// Makes the framebuffer, the program and the vertex buffer for drawing
    /// `triangles` (as [`Gl::draw`] does), without drawing: for timing the
    /// draw alone, again and again ([`GlDrawing::draw`]).
    pub fn upload(
        &self,
        (width, height): (u32, u32),
        triangles: &[GpuTriangle],
        depth: Option<(DepthTest, u32)>,
    ) -> Result<GlDrawing<'_>, GpuError> {
        let gl = &self.gl;
        let (w, h) = (width as i32, height as i32);
        let failed = |step: &'static str| move |reason: String| GpuError::Refused { step, reason };
        // SAFETY: every call below runs on the context made current by `open`, with objects it
        // created; buffers passed in outlive the calls that read them.
        unsafe {
            let framebuffer = gl.create_framebuffer().map_err(failed("glGenFramebuffers"))?;
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(framebuffer));
            let colour = gl.create_renderbuffer().map_err(failed("glGenRenderbuffers"))?;
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(colour));
            gl.renderbuffer_storage(glow::RENDERBUFFER, glow::RGBA8, w, h);
            gl.framebuffer_renderbuffer(glow::FRAMEBUFFER, glow::COLOR_ATTACHMENT0, glow::RENDERBUFFER, Some(colour));
            let depth_buffer = gl.create_renderbuffer().map_err(failed("glGenRenderbuffers"))?;
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(depth_buffer));
            gl.renderbuffer_storage(glow::RENDERBUFFER, glow::DEPTH_COMPONENT24, w, h);
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::DEPTH_ATTACHMENT,
                glow::RENDERBUFFER,
                Some(depth_buffer),
            );
            let program = self.program()?;
            let array = gl.create_vertex_array().map_err(failed("glGenVertexArrays"))?;
            let buffer = gl.create_buffer().map_err(failed("glGenBuffers"))?;
            // From here on the objects are deleted when the drawing is dropped, whatever fails.
            let drawing = GlDrawing {
                gl: self,
                size: (width, height),
                objects: (framebuffer, colour, depth_buffer, program, array, buffer),
                count: (triangles.len() * 3) as i32,
                depth_max: depth.map_or(1, |(_, max)| max.max(1)),
            };
            if gl.check_framebuffer_status(glow::FRAMEBUFFER) != glow::FRAMEBUFFER_COMPLETE {
                return Err(GpuError::Refused { step: "glCheckFramebufferStatus", reason: "incomplete".into() });
            }
            gl.use_program(Some(program));
            gl.viewport(0, 0, w, h);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            match depth {
                Some((test, _)) => {
                    gl.enable(glow::DEPTH_TEST);
                    let (function, clear) = match test {
                        DepthTest::Greater => (glow::GREATER, 0.0),
                        DepthTest::GreaterEqual => (glow::GEQUAL, 0.0),
                        DepthTest::Less => (glow::LESS, 1.0),
                        DepthTest::LessEqual => (glow::LEQUAL, 1.0),
                        DepthTest::Always => (glow::ALWAYS, 0.0),
                        DepthTest::Never => (glow::NEVER, 0.0),
                    };
                    gl.depth_func(function);
                    gl.clear_depth(clear);
                }
                None => gl.disable(glow::DEPTH_TEST),
            }
            // Per vertex: x, y, z in normalized device coordinates, then the colour.
            let depth_max = drawing.depth_max;
            let mut data: Vec<f32> = Vec::with_capacity(triangles.len() * 21);
            for triangle in triangles {
                let colour = [triangle.id & 0xff, (triangle.id >> 8) & 0xff, (triangle.id >> 16) & 0xff, 255];
                for [x, y, z] in triangle.vertices {
                    data.extend([
                        (2.0 * x / f64::from(width) - 1.0) as f32,
                        (2.0 * y / f64::from(height) - 1.0) as f32,
                        (2.0 * z / f64::from(depth_max) - 1.0) as f32,
                    ]);
                    data.extend(colour.map(|c| c as f32 / 255.0));
                }
            }
            gl.bind_vertex_array(Some(array));
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(buffer));
            let bytes: Vec<u8> = data.iter().flat_map(|v| v.to_ne_bytes()).collect();
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STATIC_DRAW);
            gl.enable_vertex_attrib_array(0);
            gl.vertex_attrib_pointer_f32(0, 3, glow::FLOAT, false, 28, 0);
            gl.enable_vertex_attrib_array(1);
            gl.vertex_attrib_pointer_f32(1, 4, glow::FLOAT, false, 28, 12);
            // The upload itself is done before anything is timed.
            gl.finish();
            Ok(drawing)
        }
    }

    /// The shaders: positions through unchanged, each triangle's colour flat.
    fn program(&self) -> Result<glow::Program, GpuError> {
        const VERTEX: &str = "#version 330 core
            layout(location = 0) in vec3 position;
            layout(location = 1) in vec4 colour;
            flat out vec4 drawn;
            void main() { gl_Position = vec4(position, 1.0); drawn = colour; }";
        const FRAGMENT: &str = "#version 330 core
            flat in vec4 drawn;
            out vec4 shown;
            void main() { shown = drawn; }";
        let gl = &self.gl;
        let failed = |step: &'static str| move |reason: String| GpuError::Refused { step, reason };
        // SAFETY: the context is current; the shaders are compiled and linked before use.
        unsafe {
            let program = gl.create_program().map_err(failed("glCreateProgram"))?;
            for (kind, source) in [(glow::VERTEX_SHADER, VERTEX), (glow::FRAGMENT_SHADER, FRAGMENT)] {
                let shader = gl.create_shader(kind).map_err(failed("glCreateShader"))?;
                gl.shader_source(shader, source);
                gl.compile_shader(shader);
                if !gl.get_shader_compile_status(shader) {
                    return Err(GpuError::Refused { step: "glCompileShader", reason: gl.get_shader_info_log(shader) });
                }
                gl.attach_shader(program, shader);
                gl.delete_shader(shader);
            }
            gl.link_program(program);
            if !gl.get_program_link_status(program) {
                return Err(GpuError::Refused { step: "glLinkProgram", reason: gl.get_program_info_log(program) });
            }
            Ok(program)
        }
    }
}

impl Drop for Gl {
    fn drop(&mut self) {
        let _ = self.egl.make_current(self.display, None, None, None);
        let _ = self.egl.destroy_context(self.display, self.context);
        let _ = self.egl.terminate(self.display);
    }
}

/// Triangles uploaded to the GPU with their framebuffer ([`Gl::upload`]),
/// ready to be drawn (again).
pub struct GlDrawing<'g> {
    gl: &'g Gl,
    size: (u32, u32),
    objects:
        (glow::Framebuffer, glow::Renderbuffer, glow::Renderbuffer, glow::Program, glow::VertexArray, glow::Buffer),
    count: i32,
    depth_max: u32,
}

impl GlDrawing<'_> {
    /// Clears the buffers and draws every triangle, and waits until the GPU
    /// has finished (`glFinish`): what a benchmark times.
    pub fn draw(&self) {
        let gl = &self.gl.gl;
        // SAFETY: the context is current and the objects bound by `upload` are alive.
        unsafe {
            gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
            gl.draw_arrays(glow::TRIANGLES, 0, self.count);
            gl.finish();
        }
    }

    /// Reads back which triangle shows at each pixel, and its depth.
    pub fn picture(&self) -> Result<GpuPicture, GpuError> {
        let gl = &self.gl.gl;
        let (width, height) = self.size;
        let (w, h) = (width as i32, height as i32);
        // SAFETY: the context is current; the slices are as large as the pixels read.
        unsafe {
            let mut rgba = vec![0u8; (width * height * 4) as usize];
            gl.read_pixels(0, 0, w, h, glow::RGBA, glow::UNSIGNED_BYTE, glow::PixelPackData::Slice(Some(&mut rgba)));
            let mut depth_bytes = vec![0u8; (width * height * 4) as usize];
            gl.read_pixels(
                0,
                0,
                w,
                h,
                glow::DEPTH_COMPONENT,
                glow::FLOAT,
                glow::PixelPackData::Slice(Some(&mut depth_bytes)),
            );
            let error = gl.get_error();
            if error != glow::NO_ERROR {
                return Err(GpuError::Refused { step: "glGetError", reason: format!("0x{error:04x}") });
            }
            let shown =
                rgba.chunks(4).map(|p| u32::from(p[0]) | u32::from(p[1]) << 8 | u32::from(p[2]) << 16).collect();
            let depth_max = f64::from(self.depth_max);
            let depth = depth_bytes
                .chunks(4)
                .map(|b| f64::from(f32::from_ne_bytes([b[0], b[1], b[2], b[3]])) * depth_max)
                .collect();
            Ok(GpuPicture { width, height, shown, depth })
        }
    }
}

impl Drop for GlDrawing<'_> {
    fn drop(&mut self) {
        let gl = &self.gl.gl;
        let (framebuffer, colour, depth, program, array, buffer) = self.objects;
        // SAFETY: the objects were created on this context and are deleted once.
        unsafe {
            gl.delete_buffer(buffer);
            gl.delete_vertex_array(array);
            gl.delete_program(program);
            gl.delete_renderbuffer(colour);
            gl.delete_renderbuffer(depth);
            gl.delete_framebuffer(framebuffer);
        }
    }
}
