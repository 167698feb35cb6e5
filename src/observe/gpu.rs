//! A real GPU implementation as a reference: the machine's OpenGL (Mesa's
//! llvmpipe, the standard software OpenGL, headless through EGL), loaded at
//! run time, so that zsim builds and runs without it and says so in one line
//! when it is absent.
//!
//! Triangles are drawn into a framebuffer object of the raster's size with
//! OpenGL's lower-left origin, which is zsim's y-up raster: pixel (x, y) is
//! zsim's pixel (x, y). A vertex at pixel units (x, y) is sent as
//! `2x/W − 1, 2y/H − 1` in `f32`, exact for the coordinates the tests use (a
//! power-of-two raster, vertices on a 1/256 grid, as llvmpipe's 8-bit subpixel
//! precision snaps them). Each triangle's colour is its number, so what is
//! read back is which triangle shows at each pixel, and its 24-bit depth.

use glow::HasContext;
use khronos_egl as egl;

use crate::raster::depth::DepthTest;

/// What went wrong reaching the machine's OpenGL.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GpuError {
    /// No `libEGL.so.1`, or one without EGL 1.5.
    NoLibrary(String),
    /// No Vulkan device (no `libvulkan.so.1`, or no driver such as lavapipe).
    NoVulkan(String),
    /// This zsim was built without the cargo feature that API needs.
    NotBuilt(&'static str),
    /// EGL, OpenGL or Vulkan refused a step.
    Refused {
        /// The step.
        step: &'static str,
        /// What was said.
        reason: String,
    },
}

impl std::fmt::Display for GpuError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&match self {
            GpuError::NoLibrary(reason) => words!("gpu-no-library", reason = reason.as_str()),
            GpuError::NoVulkan(reason) => words!("gpu-no-vulkan", reason = reason.as_str()),
            GpuError::NotBuilt(feature) => words!("gpu-not-built", feature = *feature),
            GpuError::Refused { step, reason } => words!("gpu-refused", step = *step, reason = reason.as_str()),
        })
    }
}

impl std::error::Error for GpuError {}

/// One triangle to draw: three vertices in pixel units `(x, y, z)` and the
/// number it is drawn with (1 … 2^24 − 1; 0 is the background).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GpuTriangle {
    /// The vertices, in pixel units; z in depth levels.
    pub vertices: [[f64; 3]; 3],
    /// Its number, read back where it shows.
    pub id: u32,
}

/// What the GPU drew.
#[derive(Debug, Clone, PartialEq)]
pub struct GpuPicture {
    /// Raster width.
    pub width: u32,
    /// Raster height.
    pub height: u32,
    /// The number of the triangle showing at each pixel, 0 where none does;
    /// row 0 (the bottom) first, as zsim counts rows.
    pub shown: Vec<u32>,
    /// The depth the GPU stored at each pixel, in depth levels
    /// (`window depth × depth_max`), row 0 first.
    pub depth: Vec<f64>,
}

impl GpuPicture {
    /// The number of the triangle showing at pixel (x, y), 0 for none.
    pub fn at(&self, x: u32, y: u32) -> u32 {
        self.shown[(y * self.width + x) as usize]
    }
}

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

fn refused(step: &'static str) -> impl Fn(egl::Error) -> GpuError {
    move |error| GpuError::Refused { step, reason: error.to_string() }
}

impl Gl {
    /// Loads `libEGL.so.1` and makes an OpenGL 3.3 core context current on
    /// this thread, with no surface.
    pub fn open() -> Result<Gl, GpuError> {
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
        (width, height): (u32, u32),
        triangles: &[GpuTriangle],
        depth: Option<(DepthTest, u32)>,
    ) -> Result<GpuPicture, GpuError> {
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
            if gl.check_framebuffer_status(glow::FRAMEBUFFER) != glow::FRAMEBUFFER_COMPLETE {
                return Err(GpuError::Refused { step: "glCheckFramebufferStatus", reason: "incomplete".into() });
            }
            let program = self.program()?;
            gl.use_program(Some(program));
            gl.viewport(0, 0, w, h);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            let depth_max = depth.map_or(1, |(_, max)| max.max(1));
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
            gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
            // Per vertex: x, y, z in normalized device coordinates, then the colour.
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
            let array = gl.create_vertex_array().map_err(failed("glGenVertexArrays"))?;
            gl.bind_vertex_array(Some(array));
            let buffer = gl.create_buffer().map_err(failed("glGenBuffers"))?;
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(buffer));
            let bytes: Vec<u8> = data.iter().flat_map(|v| v.to_ne_bytes()).collect();
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STATIC_DRAW);
            gl.enable_vertex_attrib_array(0);
            gl.vertex_attrib_pointer_f32(0, 3, glow::FLOAT, false, 28, 0);
            gl.enable_vertex_attrib_array(1);
            gl.vertex_attrib_pointer_f32(1, 4, glow::FLOAT, false, 28, 12);
            gl.draw_arrays(glow::TRIANGLES, 0, (triangles.len() * 3) as i32);
            gl.finish();
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
            gl.delete_buffer(buffer);
            gl.delete_vertex_array(array);
            gl.delete_program(program);
            gl.delete_renderbuffer(colour);
            gl.delete_renderbuffer(depth_buffer);
            gl.delete_framebuffer(framebuffer);
            if error != glow::NO_ERROR {
                return Err(GpuError::Refused { step: "glGetError", reason: format!("0x{error:04x}") });
            }
            let shown =
                rgba.chunks(4).map(|p| u32::from(p[0]) | u32::from(p[1]) << 8 | u32::from(p[2]) << 16).collect();
            let depth = depth_bytes
                .chunks(4)
                .map(|b| f64::from(f32::from_ne_bytes([b[0], b[1], b[2], b[3]])) * f64::from(depth_max))
                .collect();
            Ok(GpuPicture { width, height, shown, depth })
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

/// Vulkan (Mesa's lavapipe where no GPU is present), driven by wgpu: triangles drawn into an
/// RGBA8 texture (and a 32-bit float depth texture), read back. Vulkan's
/// framebuffer counts rows from the top: zsim's pixel (x, y) is the
/// texture's column x, row `side − 1 − y`.
#[cfg(feature = "vulkan")]
pub struct Vulkan {
    device: wgpu::Device,
    queue: wgpu::Queue,
    plain: wgpu::RenderPipeline,
    depth: wgpu::RenderPipeline,
    renderer: String,
}

#[cfg(feature = "vulkan")]
impl std::fmt::Debug for Vulkan {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Vulkan").field("renderer", &self.renderer).finish_non_exhaustive()
    }
}

#[cfg(feature = "vulkan")]
impl Vulkan {
    /// The machine's first Vulkan adapter (lavapipe where no GPU is present).
    pub fn open() -> Result<Vulkan, GpuError> {
        let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle();
        descriptor.backends = wgpu::Backends::VULKAN;
        let instance = wgpu::Instance::new(descriptor);
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
            .map_err(|error| GpuError::NoVulkan(error.to_string()))?;
        let info = adapter.get_info();
        let renderer = format!("{} ({})", info.name, info.driver_info);
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default()))
            .map_err(|error| GpuError::Refused { step: "requestDevice", reason: error.to_string() })?;
        let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: None,
            source: wgpu::ShaderSource::Wgsl(
                "struct Out { @builtin(position) position: vec4<f32>, @location(0) @interpolate(flat) colour: vec4<f32> };
                 @vertex fn vs(@location(0) position: vec3<f32>, @location(1) colour: vec4<f32>) -> Out {
                     return Out(vec4<f32>(position, 1.0), colour);
                 }
                 @fragment fn fs(input: Out) -> @location(0) vec4<f32> { return input.colour; }"
                    .into(),
            ),
        });
        let pipeline = |depth: Option<wgpu::DepthStencilState>| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: None,
                layout: None,
                vertex: wgpu::VertexState {
                    module: &shader,
                    entry_point: Some("vs"),
                    compilation_options: Default::default(),
                    buffers: &[Some(wgpu::VertexBufferLayout {
                        array_stride: 28,
                        step_mode: wgpu::VertexStepMode::Vertex,
                        attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x4],
                    })],
                },
                primitive: wgpu::PrimitiveState::default(),
                depth_stencil: depth,
                multisample: wgpu::MultisampleState::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &shader,
                    entry_point: Some("fs"),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::TextureFormat::Rgba8Unorm.into())],
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let plain = pipeline(None);
        let depth = pipeline(Some(wgpu::DepthStencilState {
            format: wgpu::TextureFormat::Depth32Float,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Greater),
            stencil: wgpu::StencilState::default(),
            bias: wgpu::DepthBiasState::default(),
        }));
        Ok(Vulkan { device, queue, plain, depth, renderer })
    }

    /// The implementation's name, e.g. `llvmpipe (LLVM 15.0.6, 256 bits) (Mesa 22.3.6)`.
    pub fn renderer(&self) -> &str {
        &self.renderer
    }

    /// Draws `triangles` (pixel units, z in 0 … 1, numbered) on `side`×`side`,
    /// with the depth test `greater` or none; which triangle shows at each
    /// pixel, row 0 at the bottom as zsim counts.
    pub fn draw(&self, side: u32, triangles: &[([[f64; 3]; 3], u32)], depth_test: bool) -> Result<Vec<u32>, GpuError> {
        use wgpu::util::DeviceExt;
        let extent = wgpu::Extent3d { width: side, height: side, depth_or_array_layers: 1 };
        let texture = |format, usage| {
            self.device.create_texture(&wgpu::TextureDescriptor {
                label: None,
                size: extent,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let colour = texture(
            wgpu::TextureFormat::Rgba8Unorm,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        );
        let depth = texture(wgpu::TextureFormat::Depth32Float, wgpu::TextureUsages::RENDER_ATTACHMENT);
        let (colour_view, depth_view) =
            (colour.create_view(&Default::default()), depth.create_view(&Default::default()));
        let mut data: Vec<u8> = Vec::new();
        for (vertices, id) in triangles {
            let rgba = [id & 0xff, (id >> 8) & 0xff, (id >> 16) & 0xff, 255].map(|c| c as f32 / 255.0);
            for [x, y, z] in vertices {
                let position =
                    [(2.0 * x / f64::from(side) - 1.0) as f32, (2.0 * y / f64::from(side) - 1.0) as f32, *z as f32];
                for v in position.into_iter().chain(rgba) {
                    data.extend(v.to_ne_bytes());
                }
            }
        }
        let vertices = self.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents: &data,
            usage: wgpu::BufferUsages::VERTEX,
        });
        let row_bytes = (side * 4).next_multiple_of(256);
        let readback = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: u64::from(row_bytes * side),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut encoder = self.device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: None,
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &colour_view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: depth_test.then_some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth_view,
                    depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(0.0), store: wgpu::StoreOp::Store }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(if depth_test { &self.depth } else { &self.plain });
            pass.set_vertex_buffer(0, vertices.slice(..));
            pass.draw(0..(triangles.len() * 3) as u32, 0..1);
        }
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &colour,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &readback,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(row_bytes),
                    rows_per_image: Some(side),
                },
            },
            extent,
        );
        self.queue.submit([encoder.finish()]);
        let refused = |step: &'static str| move |reason: String| GpuError::Refused { step, reason };
        let (sender, mapped) = std::sync::mpsc::channel();
        readback.slice(..).map_async(wgpu::MapMode::Read, move |result| {
            let _ = sender.send(result);
        });
        self.device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| refused("poll")(e.to_string()))?;
        mapped
            .recv()
            .map_err(|e| refused("mapAsync")(e.to_string()))?
            .map_err(|e| refused("mapAsync")(e.to_string()))?;
        let bytes =
            readback.slice(..).get_mapped_range().map_err(|e| refused("getMappedRange")(e.to_string()))?.to_vec();
        let mut shown = vec![0; (side * side) as usize];
        for y in 0..side {
            let top_row = side - 1 - y;
            for x in 0..side {
                let at = (top_row * row_bytes + x * 4) as usize;
                shown[(y * side + x) as usize] =
                    u32::from(bytes[at]) | u32::from(bytes[at + 1]) << 8 | u32::from(bytes[at + 2]) << 16;
            }
        }
        Ok(shown)
    }
}

/// One cell where the GPU shows another polygon than zsim.
#[derive(Debug, Clone, PartialEq)]
pub struct GpuDifference {
    /// The pixel.
    pub x: u32,
    /// The pixel's row.
    pub y: u32,
    /// The polygon (0-based) the GPU shows, if any.
    pub gpu: Option<usize>,
    /// The polygon zsim shows under the scene's own rules.
    pub book: Option<usize>,
    /// The polygon zsim shows under the API's preset.
    pub preset: Option<usize>,
    /// Why, in words: the edge a centre lies on and the rule that decides
    /// it, or the depths that decided it.
    pub why: String,
}

/// The scene drawn by the GPU beside zsim: every cell that differs.
#[derive(Debug, Clone, PartialEq)]
pub struct GpuComparison {
    /// The implementation, as it names itself.
    pub renderer: String,
    /// The preset of the API drawn with.
    pub preset: crate::rules::Preset,
    /// The cells that differ, bottom row first.
    pub differences: Vec<GpuDifference>,
    /// Polygons drawn as a fan of triangles though not convex (their
    /// picture on the GPU is not the polygon's).
    pub not_convex: Vec<usize>,
}

/// A GPU API `compare` draws with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GpuApi {
    /// OpenGL through EGL; compared with the `gl` preset.
    Gl,
    /// Vulkan (needs zsim built with its `vulkan` feature); compared with
    /// the `vulkan` preset.
    Vulkan,
}

/// Draws `scene` with the machine's GPU through `api` and compares what
/// shows at every pixel with zsim under the scene's own rules and under the
/// API's preset. Only the plain algorithm is compared (no per-pixel effects,
/// no antialiasing).
pub fn compare(scene: &crate::scene::Scene, api: GpuApi) -> Result<GpuComparison, crate::error::Error> {
    use crate::error::Usage;
    use crate::numbers::to_f64;
    use crate::rules::{Preset, Rules};
    if scene.has_pixel_effects() || scene.effects.antialias.is_some() {
        return Err(Usage::CompareGpuPlainOnly.into());
    }
    let preset = match api {
        GpuApi::Gl => Preset::Gl,
        GpuApi::Vulkan => Preset::Vulkan,
    };
    let shows = |rules: Rules| {
        // Each polygon writes its number, so the framebuffer says which polygon shows.
        let mut numbered = scene.clone();
        numbered.frame_bits = 32;
        numbered.background = 0;
        numbered.rules = rules;
        for (index, polygon) in numbered.polygons.iter_mut().enumerate() {
            polygon.value = index as u32 + 1;
        }
        let mut simulation = crate::simulate::simulation::Simulation::new(&numbered);
        simulation.finish(&mut crate::simulate::events::Unobserved);
        simulation.into_buffers()
    };
    let api_rules = Rules { store: scene.rules.store, ..Rules::preset(preset) };
    let (book, in_api) = (shows(scene.rules), shows(api_rules));
    let (width, height) = (scene.width, scene.height);
    // A margin keeps vertices near the raster inside the GPU's view volume, unclipped.
    let inside = |v: f64, side: u32| (-256.0..=f64::from(side) + 256.0).contains(&v);
    let near = scene
        .polygons
        .iter()
        .flat_map(|p| p.vertices())
        .all(|v| inside(to_f64(&v[0]), width) && inside(to_f64(&v[1]), height));
    let margin = if near { 256 } else { 0 };
    let mut triangles = Vec::new();
    let mut not_convex = Vec::new();
    for (index, polygon) in scene.polygons.iter().enumerate() {
        if crate::simulate::setup::fate(scene, index) != crate::simulate::events::Fate::Drawn {
            continue;
        }
        let points: Vec<[f64; 3]> = polygon
            .vertices()
            .iter()
            .map(|v| [to_f64(&v[0]) + f64::from(margin), to_f64(&v[1]) + f64::from(margin), to_f64(&v[2])])
            .collect();
        if !convex(&points) {
            not_convex.push(index);
        }
        for i in 1..points.len() - 1 {
            triangles.push(GpuTriangle { vertices: [points[0], points[i], points[i + 1]], id: index as u32 + 1 });
        }
    }
    let no_gpu = |error: GpuError| Usage::NoGpu { reason: error.to_string() };
    let (renderer, picture) = match api {
        GpuApi::Gl => {
            let gl = Gl::open().map_err(no_gpu)?;
            let depth = Some((scene.depth_test, scene.depth_max()));
            let picture = gl.draw((width + 2 * margin, height + 2 * margin), &triangles, depth).map_err(no_gpu)?;
            (gl.renderer().to_string(), picture)
        }
        GpuApi::Vulkan => vulkan_picture(scene, &triangles, margin).map_err(no_gpu)?,
    };
    let polygon = |id: u32| (id > 0).then(|| id as usize - 1);
    let mut differences = Vec::new();
    for y in 0..height {
        for x in 0..width {
            let gpu = polygon(picture.at(x + margin, y + margin));
            let (in_book, in_preset) = (polygon(book.frame(x, y)), polygon(in_api.frame(x, y)));
            if gpu == in_book && gpu == in_preset {
                continue;
            }
            let involved = [gpu, in_book, in_preset];
            let tie = involved
                .iter()
                .flatten()
                .find_map(|&i| crate::observe::tie::tie_text(api_rules, scene.polygons[i].vertices(), x, y));
            let why = tie.unwrap_or_else(|| {
                let exact = |i: Option<usize>| {
                    i.map_or_else(
                        || words!("gpu-background"),
                        |i| {
                            let depth = crate::raster::depth::depth_at_centre(scene.polygons[i].geometry(), x, y);
                            words!(
                                "gpu-exact-depth",
                                polygon = crate::observe::explain::polygon_name(scene, i),
                                depth = crate::numbers::exact_and_decimal(depth.value())
                            )
                        },
                    )
                };
                match picture.depth.get(((y + margin) * picture.width + x + margin) as usize) {
                    Some(stored) => {
                        words!("gpu-why-depth", gpu = format!("{stored:.3}"), shown = exact(gpu), book = exact(in_book))
                    }
                    None => words!("gpu-why-depth-unread", shown = exact(gpu), book = exact(in_book)),
                }
            });
            differences.push(GpuDifference { x, y, gpu, book: in_book, preset: in_preset, why });
        }
    }
    Ok(GpuComparison { renderer, preset, differences, not_convex })
}

/// The scene's triangles drawn by Vulkan, as a picture of `width + 2·margin`
/// on each side (its depths are not read back).
#[cfg(feature = "vulkan")]
fn vulkan_picture(
    scene: &crate::scene::Scene,
    triangles: &[GpuTriangle],
    margin: u32,
) -> Result<(String, GpuPicture), GpuError> {
    let vulkan = Vulkan::open()?;
    let side = scene.width.max(scene.height) + 2 * margin;
    let max = f64::from(scene.depth_max().max(1));
    // Vulkan's pipeline here tests `greater`; `less` is the same order on 1 − z.
    let depth = |z: f64| match scene.depth_test {
        DepthTest::Greater => Ok(z / max),
        DepthTest::Less => Ok(1.0 - z / max),
        other => Err(GpuError::Refused { step: "depth test", reason: other.name().to_string() }),
    };
    let mut drawn = Vec::with_capacity(triangles.len());
    for triangle in triangles {
        let [a, b, c] = triangle.vertices;
        let vertex = |[x, y, z]: [f64; 3]| depth(z).map(|z| [x, y, z]);
        drawn.push(([vertex(a)?, vertex(b)?, vertex(c)?], triangle.id));
    }
    let shown = vulkan.draw(side, &drawn, true)?;
    Ok((vulkan.renderer().to_string(), GpuPicture { width: side, height: side, shown, depth: Vec::new() }))
}

/// Without the `vulkan` feature there is no Vulkan to draw with.
#[cfg(not(feature = "vulkan"))]
fn vulkan_picture(_: &crate::scene::Scene, _: &[GpuTriangle], _: u32) -> Result<(String, GpuPicture), GpuError> {
    Err(GpuError::NotBuilt("vulkan"))
}

/// Whether a polygon's vertices (x, y) turn one way only.
fn convex(points: &[[f64; 3]]) -> bool {
    let n = points.len();
    let turns: Vec<f64> = (0..n)
        .map(|i| {
            let (a, b, c) = (points[i], points[(i + 1) % n], points[(i + 2) % n]);
            (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
        })
        .filter(|t| *t != 0.0)
        .collect();
    turns.iter().all(|t| *t > 0.0) || turns.iter().all(|t| *t < 0.0)
}

impl GpuComparison {
    /// The comparison in the reader's language, as `zsim run --compare-gpu`
    /// prints it.
    pub fn text(&self, scene: &crate::scene::Scene, path: &str) -> String {
        let name = |i: Option<usize>| {
            i.map_or_else(|| words!("gpu-background"), |i| crate::observe::explain::polygon_name(scene, i))
        };
        let preset = match self.preset {
            crate::rules::Preset::Vulkan => "vulkan",
            _ => "gl",
        };
        let mut text = words!("gpu-heading", path = path, renderer = self.renderer.as_str(), preset = preset) + "\n";
        for &index in &self.not_convex {
            text.push_str(&format!("  {}\n", words!("gpu-not-convex", polygon = name(Some(index)))));
        }
        if self.differences.is_empty() {
            text.push_str(&format!("{}\n", words!("gpu-same")));
            return text;
        }
        text.push_str(&format!("{}\n", words!("gpu-differ", count = self.differences.len())));
        for d in &self.differences {
            let line = words!(
                "gpu-cell",
                x = d.x.to_string(),
                y = d.y.to_string(),
                gpu = name(d.gpu),
                book = name(d.book),
                covered = name(d.preset),
                preset = preset
            );
            text.push_str(&format!("  {line}\n      {}\n", d.why));
        }
        text
    }
}
