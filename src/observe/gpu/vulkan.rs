//! Vulkan through wgpu (see the module above).

use super::GpuError;

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

/// Built without the `vulkan` feature: a Vulkan that never opens, so that
/// `--compare-gpu vulkan` and the tests say what is missing.
#[cfg(not(feature = "vulkan"))]
#[derive(Debug)]
pub struct Vulkan {
    never: std::convert::Infallible,
}

#[cfg(not(feature = "vulkan"))]
impl Vulkan {
    /// Always [`GpuError::NotBuilt`].
    pub fn open() -> Result<Vulkan, GpuError> {
        Err(GpuError::NotBuilt("vulkan"))
    }

    /// Never reached: no `Vulkan` is made.
    pub fn renderer(&self) -> &str {
        match self.never {}
    }

    /// Never reached: no `Vulkan` is made.
    pub fn draw(&self, _: u32, _: &[([[f64; 3]; 3], u32)], _: bool) -> Result<Vec<u32>, GpuError> {
        match self.never {}
    }
}
