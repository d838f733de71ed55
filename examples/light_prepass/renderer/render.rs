//! The three passes on a wgpu device: (a) depth, normal and roughness (log or GGX) into the
//! G-buffer's render targets, (b) light volumes blended additively into the light buffer(s),
//! (c) a second geometry pass that combines light with material. Timestamp queries time each
//! pass when the adapter has them.

use super::scene::SceneData;
use super::{Config, LightFormat, MAX_POWER, Storage, shaders, volumes};
use glam::Vec2;
use prepass::projection::{DepthConvention, Projection};
use prepass::scene::{DepthStorage, LightBuffers, NormalEncoding};
use wgpu::util::DeviceExt as _;

/// The crate's harness device (the same adapter choice, `WGPU_BACKEND` and `PREPASS_ADAPTER`
/// included; it turns on timestamps and the adapter's own multisample counts where it has them).
pub struct Device {
    gpu: prepass::harness::Gpu,
    /// Whether timestamp queries are on.
    pub timestamps: bool,
}

impl Device {
    /// Open the best adapter (a GPU before a software one). Fails with the fix when none exists,
    /// or when the adapter is wgpu's GL backend: the lighting passes read the depth target with
    /// `textureLoad`, which naga's GLSL backend cannot write for depth textures.
    pub fn new() -> Result<Self, String> {
        let gpu = prepass::harness::Gpu::new().map_err(|e| e.to_string())?;
        if gpu.adapter_info().backend == wgpu::Backend::Gl {
            return Err(format!(
                "the light pre-pass renderer reads its depth target with textureLoad, which naga \
                 cannot translate to GLSL for depth textures, so it does not run on wgpu's GL \
                 backend ({}): run it on a Vulkan, Metal or Direct3D 12 adapter (unset \
                 WGPU_BACKEND, or set it to vulkan; lavapipe is one: bash .ci/setup-adapter)",
                gpu.adapter_info().name
            ));
        }
        let timestamps = gpu
            .device()
            .features()
            .contains(wgpu::Features::TIMESTAMP_QUERY);
        Ok(Device { gpu, timestamps })
    }

    /// The device.
    pub fn device(&self) -> &wgpu::Device {
        self.gpu.device()
    }

    /// Its queue.
    pub fn queue(&self) -> &wgpu::Queue {
        self.gpu.queue()
    }

    /// One line naming the adapter and driver.
    pub fn describe(&self) -> String {
        let i = self.gpu.adapter_info();
        format!("{} ({:?}, {})", i.name, i.backend, i.driver_info)
    }

    /// Whether the adapter is Mesa's lavapipe (or another CPU rasteriser).
    pub fn is_software(&self) -> bool {
        self.gpu.is_software()
    }

    /// The MSAA counts every format of `cfg`'s targets supports.
    pub fn sample_counts(&self, cfg: &Config) -> Vec<u32> {
        let formats = formats(cfg);
        [1u32, 2, 4, 8]
            .into_iter()
            .filter(|&n| {
                formats.iter().all(|f| {
                    self.gpu
                        .adapter()
                        .get_texture_format_features(*f)
                        .flags
                        .sample_count_supported(n)
                })
            })
            .collect()
    }
}

/// The fat G-buffer read back (single-sampled frames only): for the test's per-pixel bound.
pub struct FatGBuffer {
    /// View-space normal xyz and the roughness code, per pixel.
    pub normal: Vec<[f32; 4]>,
    /// View depth (0 where there is no geometry).
    pub view_z: Vec<f32>,
}

/// A diet G-buffer read back (single-sampled frames only): the test decodes it with the Rust
/// twins and checks each target against the fat one and the encodings' derived errors.
pub struct DietGBuffer {
    /// Each colour target's texels, in `Scene::gbuffer()` order after the depth target
    /// (normal, then the 24-bit depth code for D24, then the roughness for the encodings
    /// without a free alpha, except Substrate, whose word holds it).
    pub targets: Vec<Vec<u8>>,
    /// The depth buffer (D32F layouts).
    pub depth: Option<Vec<f32>>,
}

/// One rendered frame.
pub struct Output {
    /// Width.
    pub width: u32,
    /// Height.
    pub height: u32,
    /// The resolved linear colour (rgba16float read back), row-major from the top.
    pub colour: Vec<[f32; 4]>,
    /// The fat G-buffer, when the layout is fat and single-sampled.
    pub fat: Option<FatGBuffer>,
    /// The diet G-buffer, when the layout is a diet one and single-sampled.
    pub diet: Option<DietGBuffer>,
    /// GPU time of passes (a), (b), (c) in milliseconds (the minimum over the repeats), or
    /// `None` when the adapter has no timestamp queries or `repeats` is 0.
    pub pass_ms: Option<[f64; 3]>,
    /// Light-pass fragments: shaded (invoked), rejected by depth bounds, discarded as sky.
    pub fragments: [u32; 3],
    /// Lights per class: sphere front faces, sphere back faces (camera inside), cone front,
    /// cone back.
    pub classes: [u32; 4],
    /// Lights left out (radius zero, negative or not finite).
    pub skipped: u32,
}

struct Target {
    format: wgpu::TextureFormat,
    clear: wgpu::Color,
}

/// The normal target's format as `Scene::gbuffer` lays it out for encoding `e` (rgb10a2unorm for
/// xyz10, oct20 and the signed octahedron, rgba8snorm for snorm8, rg8unorm for oct16, rgba8unorm otherwise).
fn normal_format(e: NormalEncoding) -> wgpu::TextureFormat {
    let scene = prepass::scene::Scene {
        normal: prepass::scene::NormalChoice {
            encoding: Some(e),
            fast_encoder: false,
        },
        ..prepass::scene::Scene::default()
    };
    scene
        .gbuffer()
        .ok()
        .and_then(|g| g.targets.into_iter().find(|t| t.name == "normal"))
        .map_or(wgpu::TextureFormat::Rgba8Unorm, |t| t.format.to_wgpu())
}

fn gbuffer_targets(cfg: &Config) -> Vec<Target> {
    let zero = wgpu::Color::TRANSPARENT;
    match cfg.storage {
        Storage::Fat => vec![
            Target {
                format: wgpu::TextureFormat::Rgba32Float,
                clear: zero,
            },
            Target {
                format: wgpu::TextureFormat::R32Float,
                clear: zero,
            },
        ],
        Storage::Diet { normal, depth } => {
            let mut t = vec![Target {
                format: normal_format(normal),
                clear: zero,
            }];
            if depth == DepthStorage::Code24Rgba8 {
                // The sky's code: 0 for reversed depth (infinitely far), 2^24 − 1 for standard.
                let c = if cfg.convention == DepthConvention::Reversed {
                    0.0
                } else {
                    1.0
                };
                t.push(Target {
                    format: wgpu::TextureFormat::Rgba8Unorm,
                    clear: wgpu::Color {
                        r: c,
                        g: c,
                        b: c,
                        a: 0.0,
                    },
                });
            }
            if shaders::roughness_target(normal) {
                t.push(Target {
                    format: wgpu::TextureFormat::R8Unorm,
                    clear: zero,
                });
            }
            t
        }
    }
}

fn depth_format(cfg: &Config) -> wgpu::TextureFormat {
    match cfg.storage {
        Storage::Diet {
            depth: DepthStorage::Code24Rgba8,
            ..
        } => wgpu::TextureFormat::Depth24PlusStencil8,
        _ => wgpu::TextureFormat::Depth32Float,
    }
}

fn light_format(cfg: &Config) -> wgpu::TextureFormat {
    match cfg.light_format {
        LightFormat::Rgba8Unorm => wgpu::TextureFormat::Rgba8Unorm,
        LightFormat::Rgba16Float => wgpu::TextureFormat::Rgba16Float,
    }
}

/// The composite pass's target (resolved, read back).
const OUT_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

fn light_count(cfg: &Config) -> usize {
    match cfg.lights_layout {
        LightBuffers::One => 1,
        LightBuffers::Two => 2,
    }
}

/// Every texture format the frame renders to.
fn formats(cfg: &Config) -> Vec<wgpu::TextureFormat> {
    let mut f: Vec<_> = gbuffer_targets(cfg).iter().map(|t| t.format).collect();
    f.push(depth_format(cfg));
    f.push(light_format(cfg));
    f.push(OUT_FORMAT);
    f
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct FrameUniform {
    view: [[f32; 4]; 4],
    proj: [[f32; 4]; 4],
    tan_half_fov: [f32; 2],
    size: [f32; 2],
    depth_k: [f32; 4],
    near: f32,
    far: f32,
    reversed: u32,
    max_power: f32,
    bounds_on: u32,
    count: u32,
    pad: [u32; 2],
}

/// Check the resolution and sample count against the device before anything is created.
pub fn check(dev: &Device, cfg: &Config) -> Result<(), String> {
    let max = dev.device().limits().max_texture_dimension_2d;
    if cfg.width == 0 || cfg.height == 0 {
        return Err(format!(
            "resolution {}×{}: width and height must be at least 1",
            cfg.width, cfg.height
        ));
    }
    if cfg.width > max || cfg.height > max {
        return Err(format!(
            "resolution {}×{} is beyond this adapter's limit of {max} pixels a side \
             (max_texture_dimension_2d of {})",
            cfg.width,
            cfg.height,
            dev.describe()
        ));
    }
    let counts = dev.sample_counts(cfg);
    if !counts.contains(&cfg.msaa) {
        return Err(format!(
            "--msaa {}: this adapter supports {:?} samples for every target of the layout \
             `{}` ({})",
            cfg.msaa,
            counts,
            cfg.layout_name(),
            dev.describe()
        ));
    }
    Ok(())
}

fn texture(
    dev: &Device,
    cfg: &Config,
    format: wgpu::TextureFormat,
    samples: u32,
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    dev.device().create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d {
            width: cfg.width,
            height: cfg.height,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: samples,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    })
}

fn tex_entry(binding: u32, ms: bool, depth: bool) -> wgpu::BindGroupLayoutEntry {
    let sample_type = if depth {
        wgpu::TextureSampleType::Depth
    } else {
        wgpu::TextureSampleType::Float { filterable: false }
    };
    typed_tex_entry(binding, ms, sample_type)
}

fn typed_tex_entry(
    binding: u32,
    ms: bool,
    sample_type: wgpu::TextureSampleType,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type,
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: ms,
        },
        count: None,
    }
}

/// A bind group of `views` at bindings 0, 1, … of `layout`.
fn texture_group<'a>(
    d: &wgpu::Device,
    label: &str,
    layout: &wgpu::BindGroupLayout,
    views: impl IntoIterator<Item = &'a wgpu::TextureView>,
) -> wgpu::BindGroup {
    let entries: Vec<_> = views
        .into_iter()
        .enumerate()
        .map(|(i, v)| wgpu::BindGroupEntry {
            binding: i as u32,
            resource: wgpu::BindingResource::TextureView(v),
        })
        .collect();
    d.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some(label),
        layout,
        entries: &entries,
    })
}

/// A colour attachment cleared to `clear` and stored (resolved into `resolve` when given).
fn cleared<'a>(
    view: &'a wgpu::TextureView,
    resolve: Option<&'a wgpu::TextureView>,
    clear: wgpu::Color,
) -> Option<wgpu::RenderPassColorAttachment<'a>> {
    Some(wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: resolve,
        ops: wgpu::Operations {
            load: wgpu::LoadOp::Clear(clear),
            store: wgpu::StoreOp::Store,
        },
    })
}

fn buffer_entry(
    binding: u32,
    visibility: wgpu::ShaderStages,
    ty: wgpu::BufferBindingType,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// Read a single-sampled texture back, `texel` bytes a texel, rows unpadded.
fn read_texture(dev: &Device, tex: &wgpu::Texture, texel: u32) -> Vec<u8> {
    read_aspect(dev, tex, texel, wgpu::TextureAspect::All)
}

fn read_aspect(
    dev: &Device,
    tex: &wgpu::Texture,
    texel: u32,
    aspect: wgpu::TextureAspect,
) -> Vec<u8> {
    let (w, h) = (tex.width(), tex.height());
    let row = w * texel;
    let padded =
        row.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
    let buf = dev.device().create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: u64::from(padded) * u64::from(h),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut enc = dev.device().create_command_encoder(&Default::default());
    enc.copy_texture_to_buffer(
        wgpu::TexelCopyTextureInfo {
            aspect,
            ..tex.as_image_copy()
        },
        wgpu::TexelCopyBufferInfo {
            buffer: &buf,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded),
                rows_per_image: None,
            },
        },
        tex.size(),
    );
    dev.queue().submit([enc.finish()]);
    let bytes = read_buffer(dev, &buf);
    let mut out = Vec::with_capacity((row * h) as usize);
    for y in 0..h {
        let s = (y * padded) as usize;
        out.extend_from_slice(&bytes[s..s + row as usize]);
    }
    out
}

fn read_buffer(dev: &Device, buf: &wgpu::Buffer) -> Vec<u8> {
    let slice = buf.slice(..);
    slice.map_async(wgpu::MapMode::Read, |r| r.expect("map a readback buffer"));
    dev.device()
        .poll(wgpu::PollType::wait_indefinitely())
        .expect("wait for the GPU");
    let v = slice.get_mapped_range().expect("mapped range").to_vec();
    buf.unmap();
    v
}

/// `tan(fov/2)` (x, y) of the frame and its lights in view space, sorted as the light pass
/// draws them.
pub fn lights_in_view(cfg: &Config, scene: &SceneData) -> (Vec2, volumes::Sorted) {
    let cam = scene.camera;
    let aspect = cfg.width as f32 / cfg.height as f32;
    let tan_y = (cam.fov_y / 2.0).tan();
    let tan = Vec2::new(tan_y * aspect, tan_y);
    let (_, sphere_scale) = volumes::icosphere();
    let (_, cone_scale) = volumes::cone();
    let sorted = volumes::sort(
        &scene.lights,
        cam.view(),
        cam.near,
        tan,
        sphere_scale,
        cone_scale,
    );
    (tan, sorted)
}

/// Render `scene` with `cfg`: the three passes, `cfg.repeats` timed times after one untimed
/// Which pipeline layout a render pipeline uses (its bind groups).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PipelineLayout {
    /// Group 0: the frame uniform.
    Geometry,
    /// Groups 0 and 1: the frame, the G-buffer and the lights.
    Light,
    /// Groups 0 and 2 (1 empty): the frame and the light buffer(s).
    Composite,
}

/// One render pipeline of the frame as [`render`] creates it, shared with
/// tests/light_prepass.rs, which has Tint build the same pipelines through Dawn.
pub struct PipelineShape {
    /// Its label.
    pub label: &'static str,
    /// Its bind groups.
    pub layout: PipelineLayout,
    /// Vertex entry point.
    pub vs: &'static str,
    /// Fragment entry point.
    pub fs: &'static str,
    /// Bytes per vertex of the one vertex buffer.
    pub vertex_stride: u64,
    /// That buffer's attributes.
    pub attributes: Vec<wgpu::VertexAttribute>,
    /// Colour targets.
    pub targets: Vec<Option<wgpu::ColorTargetState>>,
    /// Faces culled.
    pub cull: wgpu::Face,
    /// Depth test and write.
    pub depth: wgpu::DepthStencilState,
    /// Samples per pixel.
    pub samples: u32,
}

/// The frame's render pipelines, in the order [`render`] uses them: the G-buffer pass, the
/// four light-volume pipelines (sphere front, sphere back, cone front, cone back), the
/// composite pass.
pub fn pipeline_shapes(cfg: &Config) -> Vec<PipelineShape> {
    let reversed = cfg.convention == DepthConvention::Reversed;
    let geo_attrs = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Uint32].to_vec();
    let vol_attrs = wgpu::vertex_attr_array![0 => Float32x3].to_vec();
    let nearer = if reversed {
        wgpu::CompareFunction::Greater
    } else {
        wgpu::CompareFunction::Less
    };
    let (in_front, behind) = if reversed {
        (
            wgpu::CompareFunction::GreaterEqual,
            wgpu::CompareFunction::LessEqual,
        )
    } else {
        (
            wgpu::CompareFunction::LessEqual,
            wgpu::CompareFunction::GreaterEqual,
        )
    };
    let depth_state = |write: bool, compare| wgpu::DepthStencilState {
        format: depth_format(cfg),
        depth_write_enabled: Some(write),
        depth_compare: Some(compare),
        stencil: Default::default(),
        bias: Default::default(),
    };
    let shape = |label, layout, vs, fs, targets, cull, depth| PipelineShape {
        label,
        layout,
        vs,
        fs,
        vertex_stride: if vs == "geo_vs" { 28 } else { 12 },
        attributes: if vs == "geo_vs" {
            geo_attrs.clone()
        } else {
            vol_attrs.clone()
        },
        targets,
        cull,
        depth,
        samples: cfg.msaa,
    };
    let gformats: Vec<Option<wgpu::ColorTargetState>> = gbuffer_targets(cfg)
        .iter()
        .map(|t| Some(t.format.into()))
        .collect();
    let additive = wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::One,
        dst_factor: wgpu::BlendFactor::One,
        operation: wgpu::BlendOperation::Add,
    };
    let ltargets: Vec<Option<wgpu::ColorTargetState>> = (0..light_count(cfg))
        .map(|_| {
            Some(wgpu::ColorTargetState {
                format: light_format(cfg),
                blend: Some(wgpu::BlendState {
                    color: additive,
                    alpha: additive,
                }),
                write_mask: wgpu::ColorWrites::ALL,
            })
        })
        .collect();
    let mut shapes = vec![shape(
        "gbuffer",
        PipelineLayout::Geometry,
        "geo_vs",
        "gbuffer_fs",
        gformats,
        wgpu::Face::Back,
        depth_state(true, nearer),
    )];
    // Camera outside: front faces where the volume is in front of the scene. Camera inside (or
    // the near plane cuts the volume): back faces where the volume is behind the scene.
    for (vs, cull, cmp) in [
        ("sphere_vs", wgpu::Face::Back, in_front),
        ("sphere_vs", wgpu::Face::Front, behind),
        ("cone_vs", wgpu::Face::Back, in_front),
        ("cone_vs", wgpu::Face::Front, behind),
    ] {
        shapes.push(shape(
            "light volume",
            PipelineLayout::Light,
            vs,
            "light_fs",
            ltargets.clone(),
            cull,
            depth_state(false, cmp),
        ));
    }
    shapes.push(shape(
        "composite",
        PipelineLayout::Composite,
        "geo_vs",
        "composite_fs",
        vec![Some(OUT_FORMAT.into())],
        wgpu::Face::Back,
        depth_state(false, wgpu::CompareFunction::Equal),
    ));
    shapes
}

/// run, then read the resolved colour back.
pub fn render(dev: &Device, cfg: &Config, scene: &SceneData) -> Result<Output, String> {
    check(dev, cfg)?;
    let d = dev.device();
    let ms = cfg.msaa > 1;
    let prepass_scene = cfg.scene();
    let crate_wgsl = prepass_scene
        .wgsl()
        .map_err(|e| format!("Scene::wgsl(): {e}"))?;
    let source = shaders::module(cfg, &crate_wgsl);
    // naga's default capabilities leave out sample-rate shading; wgpu validates the
    // multisampled module itself with the device's.
    if !ms {
        prepass::wgsl::parse_and_validate(&source)
            .map_err(|e| format!("the frame's WGSL is invalid ({}): {e}", cfg.layout_name()))?;
    }
    let scope = d.push_error_scope(wgpu::ErrorFilter::Validation);
    let module = d.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("light_prepass"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });

    // ---- uniforms and buffers ----
    let cam = scene.camera;
    let aspect = cfg.width as f32 / cfg.height as f32;
    let projection = Projection::new(cam.near, cfg.far, cfg.convention)
        .map_err(|e| format!("projection: {e}"))?;
    let proj = projection.perspective_rh(cam.fov_y, aspect);
    let view = cam.view();
    let (tan, sorted) = lights_in_view(cfg, scene);
    let reversed = cfg.convention == DepthConvention::Reversed;
    let depth_k = match (cfg.storage, reversed) {
        (_, true) => {
            let k = projection
                .reversed_depth_consts()
                .expect("a projection of the convention these constants read")
                .to_wgsl();
            [k[0], k[1], k[2], 0.0]
        }
        (
            Storage::Diet {
                depth: DepthStorage::Code24Rgba8,
                ..
            },
            false,
        ) => {
            let k = projection
                .depth24_consts()
                .expect("a projection of the convention these constants read")
                .to_wgsl();
            [k[0], k[1], 0.0, 0.0]
        }
        (_, false) => {
            let k = projection
                .depth_consts()
                .expect("a projection of the convention these constants read")
                .to_wgsl();
            [k[0], k[1], k[2], 0.0]
        }
    };
    let uniform = FrameUniform {
        view: view.to_cols_array_2d(),
        proj: proj.to_cols_array_2d(),
        tan_half_fov: tan.to_array(),
        size: [cfg.width as f32, cfg.height as f32],
        depth_k,
        near: cam.near,
        far: cfg.far,
        reversed: u32::from(reversed),
        max_power: MAX_POWER,
        bounds_on: u32::from(cfg.depth_bounds),
        count: 1,
        pad: [0; 2],
    };
    let (sphere_mesh, _) = volumes::icosphere();
    let (cone_mesh, _) = volumes::cone();
    let init = |contents: &[u8], usage| {
        d.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents,
            usage,
        })
    };
    let frame_buf = init(
        bytemuck::bytes_of(&uniform),
        wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
    );
    let materials = init(
        bytemuck::cast_slice(&scene.materials),
        wgpu::BufferUsages::STORAGE,
    );
    let light_data: Vec<volumes::LightGpu> = if sorted.lights.is_empty() {
        vec![bytemuck::Zeroable::zeroed()]
    } else {
        sorted.lights.clone()
    };
    let lights = init(
        bytemuck::cast_slice(&light_data),
        wgpu::BufferUsages::STORAGE,
    );
    let counters = init(
        &[0u8; 16],
        wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST,
    );
    let geometry = init(
        bytemuck::cast_slice(&scene.vertices),
        wgpu::BufferUsages::VERTEX,
    );
    let sphere_vb = init(
        bytemuck::cast_slice(&sphere_mesh),
        wgpu::BufferUsages::VERTEX,
    );
    let cone_vb = init(bytemuck::cast_slice(&cone_mesh), wgpu::BufferUsages::VERTEX);

    // ---- targets ----
    let attach = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
    let gtargets = gbuffer_targets(cfg);
    let gtex: Vec<wgpu::Texture> = gtargets
        .iter()
        .map(|t| {
            texture(
                dev,
                cfg,
                t.format,
                cfg.msaa,
                attach | wgpu::TextureUsages::COPY_SRC,
            )
        })
        .collect();
    let gviews: Vec<wgpu::TextureView> = gtex
        .iter()
        .map(|t| t.create_view(&Default::default()))
        .collect();
    let dformat = depth_format(cfg);
    let depth = texture(
        dev,
        cfg,
        dformat,
        cfg.msaa,
        attach | wgpu::TextureUsages::COPY_SRC,
    );
    let depth_view = depth.create_view(&Default::default());
    let depth_sample_view = depth.create_view(&wgpu::TextureViewDescriptor {
        aspect: wgpu::TextureAspect::DepthOnly,
        ..Default::default()
    });
    let lformat = light_format(cfg);
    let ltex: Vec<wgpu::Texture> = (0..light_count(cfg))
        .map(|_| texture(dev, cfg, lformat, cfg.msaa, attach))
        .collect();
    let lviews: Vec<wgpu::TextureView> = ltex
        .iter()
        .map(|t| t.create_view(&Default::default()))
        .collect();
    let out_format = OUT_FORMAT;
    let resolved = texture(
        dev,
        cfg,
        out_format,
        1,
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
    );
    let resolved_view = resolved.create_view(&Default::default());
    let ms_out = ms.then(|| {
        texture(
            dev,
            cfg,
            out_format,
            cfg.msaa,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        )
    });
    let ms_out_view = ms_out.as_ref().map(|t| t.create_view(&Default::default()));

    // ---- bind groups ----
    let vf = wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT;
    let g0_layout = d.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("frame"),
        entries: &[
            buffer_entry(0, vf, wgpu::BufferBindingType::Uniform),
            buffer_entry(1, vf, wgpu::BufferBindingType::Storage { read_only: true }),
            buffer_entry(2, vf, wgpu::BufferBindingType::Storage { read_only: true }),
            buffer_entry(
                3,
                wgpu::ShaderStages::FRAGMENT,
                wgpu::BufferBindingType::Storage { read_only: false },
            ),
        ],
    });
    let g0 = d.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("frame"),
        layout: &g0_layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: frame_buf.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: materials.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: lights.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 3,
                resource: counters.as_entire_binding(),
            },
        ],
    });
    // Light pass, group 1: the G-buffer as the shaders bind it (see shaders::module).
    let mut g1_entries = Vec::new();
    let mut g1_views: Vec<&wgpu::TextureView> = Vec::new();
    match cfg.storage {
        Storage::Fat => {
            g1_entries.push(tex_entry(0, ms, false));
            g1_entries.push(tex_entry(1, ms, false));
            g1_views.extend([&gviews[0], &gviews[1]]);
        }
        Storage::Diet { normal, depth } => {
            // Substrate's word is an r32uint texel, read as u32.
            g1_entries.push(if normal == NormalEncoding::Substrate {
                typed_tex_entry(0, ms, wgpu::TextureSampleType::Uint)
            } else {
                tex_entry(0, ms, false)
            });
            g1_views.push(&gviews[0]);
            let mut next = 1;
            if depth == DepthStorage::Code24Rgba8 {
                g1_entries.push(tex_entry(1, ms, false));
                g1_views.push(&gviews[1]);
                next = 2;
            } else {
                g1_entries.push(tex_entry(1, ms, true));
                g1_views.push(&depth_sample_view);
            }
            if shaders::roughness_target(normal) {
                g1_entries.push(tex_entry(2, ms, false));
                g1_views.push(&gviews[next]);
            }
        }
    }
    let g1_layout = d.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("gbuffer"),
        entries: &g1_entries,
    });
    let g1 = texture_group(d, "gbuffer", &g1_layout, g1_views.iter().copied());
    let g2_layout = d.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("light buffers"),
        entries: &(0..light_count(cfg) as u32)
            .map(|i| tex_entry(i, ms, false))
            .collect::<Vec<_>>(),
    });
    let g2 = texture_group(d, "light buffers", &g2_layout, &lviews);
    let empty = d.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("empty"),
        entries: &[],
    });
    let empty_group = d.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("empty"),
        layout: &empty,
        entries: &[],
    });
    let layout = |groups: &[&wgpu::BindGroupLayout]| {
        let g: Vec<Option<&wgpu::BindGroupLayout>> = groups.iter().map(|g| Some(*g)).collect();
        d.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: None,
            bind_group_layouts: &g,
            immediate_size: 0,
        })
    };
    let geo_layout = layout(&[&g0_layout]);
    let light_layout = layout(&[&g0_layout, &g1_layout]);
    let comp_layout = layout(&[&g0_layout, &empty, &g2_layout]);

    // ---- pipelines ----
    let shapes = pipeline_shapes(cfg);
    let mut pipes = shapes.iter().map(|p| {
        let layout = match p.layout {
            PipelineLayout::Geometry => &geo_layout,
            PipelineLayout::Light => &light_layout,
            PipelineLayout::Composite => &comp_layout,
        };
        d.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(p.label),
            layout: Some(layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some(p.vs),
                compilation_options: Default::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: p.vertex_stride,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &p.attributes,
                })],
            },
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some(p.fs),
                compilation_options: Default::default(),
                targets: &p.targets,
            }),
            primitive: wgpu::PrimitiveState {
                cull_mode: Some(p.cull),
                ..Default::default()
            },
            depth_stencil: Some(p.depth.clone()),
            multisample: wgpu::MultisampleState {
                count: p.samples,
                ..Default::default()
            },
            multiview_mask: None,
            cache: None,
        })
    });
    let gbuffer_pipe = pipes.next().unwrap();
    let light_pipes: [wgpu::RenderPipeline; 4] = std::array::from_fn(|_| pipes.next().unwrap());
    let comp_pipe = pipes.next().unwrap();
    if let Some(e) = pollster::block_on(scope.pop()) {
        return Err(format!(
            "wgpu rejected the frame ({}): {e}",
            cfg.layout_name()
        ));
    }

    // ---- timestamps ----
    let queries = dev.timestamps.then(|| {
        let set = d.create_query_set(&wgpu::QuerySetDescriptor {
            label: None,
            ty: wgpu::QueryType::Timestamp,
            count: 6,
        });
        let resolve = d.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: 48,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let staging = d.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: 48,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        (set, resolve, staging)
    });
    let counters_staging = d.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 16,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let depth_clear = if reversed { 0.0 } else { 1.0 };
    let sky = wgpu::Color {
        r: 0.004,
        g: 0.006,
        b: 0.012,
        a: 1.0,
    };
    let mut best = [f64::INFINITY; 3];
    let mut fragments = [0u32; 3];
    for run in 0..=cfg.repeats {
        // Run 0 (untimed) counts the light pass's fragments; the timed runs skip the atomics.
        let counting = FrameUniform {
            count: u32::from(run == 0),
            ..uniform
        };
        dev.queue()
            .write_buffer(&frame_buf, 0, bytemuck::bytes_of(&counting));
        let mut enc = d.create_command_encoder(&Default::default());
        enc.clear_buffer(&counters, 0, None);
        let ts = |k: u32| {
            queries
                .as_ref()
                .map(|(set, _, _)| wgpu::RenderPassTimestampWrites {
                    query_set: set,
                    beginning_of_pass_write_index: Some(2 * k),
                    end_of_pass_write_index: Some(2 * k + 1),
                })
        };
        {
            let colour: Vec<_> = gviews
                .iter()
                .zip(&gtargets)
                .map(|(v, t)| cleared(v, None, t.clear))
                .collect();
            let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("(a) G-buffer"),
                color_attachments: &colour,
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth_view,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(depth_clear),
                        store: wgpu::StoreOp::Store,
                    }),
                    stencil_ops: (dformat == wgpu::TextureFormat::Depth24PlusStencil8).then_some(
                        wgpu::Operations {
                            load: wgpu::LoadOp::Clear(0),
                            store: wgpu::StoreOp::Store,
                        },
                    ),
                }),
                timestamp_writes: ts(0),
                ..Default::default()
            });
            pass.set_pipeline(&gbuffer_pipe);
            pass.set_bind_group(0, &g0, &[]);
            pass.set_vertex_buffer(0, geometry.slice(..));
            pass.draw(0..scene.vertices.len() as u32, 0..1);
        }
        {
            let colour: Vec<_> = lviews
                .iter()
                .map(|v| cleared(v, None, wgpu::Color::TRANSPARENT))
                .collect();
            // The depth buffer is read-only here, so the D32F layout can sample it as well.
            let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("(b) light volumes"),
                color_attachments: &colour,
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth_view,
                    depth_ops: None,
                    stencil_ops: None,
                }),
                timestamp_writes: ts(1),
                ..Default::default()
            });
            pass.set_bind_group(0, &g0, &[]);
            pass.set_bind_group(1, &g1, &[]);
            for (k, p) in light_pipes.iter().enumerate() {
                let range = sorted.ranges[k].clone();
                if range.is_empty() {
                    continue;
                }
                let (vb, n) = if k < 2 {
                    (&sphere_vb, sphere_mesh.len())
                } else {
                    (&cone_vb, cone_mesh.len())
                };
                pass.set_pipeline(p);
                pass.set_vertex_buffer(0, vb.slice(..));
                pass.draw(0..n as u32, range);
            }
        }
        {
            let (view, resolve_target) = match &ms_out_view {
                Some(v) => (v, Some(&resolved_view)),
                None => (&resolved_view, None),
            };
            let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("(c) composite"),
                color_attachments: &[cleared(view, resolve_target, sky)],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth_view,
                    depth_ops: None,
                    stencil_ops: None,
                }),
                timestamp_writes: ts(2),
                ..Default::default()
            });
            pass.set_pipeline(&comp_pipe);
            pass.set_bind_group(0, &g0, &[]);
            pass.set_bind_group(1, &empty_group, &[]);
            pass.set_bind_group(2, &g2, &[]);
            pass.set_vertex_buffer(0, geometry.slice(..));
            pass.draw(0..scene.vertices.len() as u32, 0..1);
        }
        if let Some((set, resolve, staging)) = &queries {
            enc.resolve_query_set(set, 0..6, resolve, 0);
            enc.copy_buffer_to_buffer(resolve, 0, staging, 0, 48);
        }
        enc.copy_buffer_to_buffer(&counters, 0, &counters_staging, 0, 16);
        dev.queue().submit([enc.finish()]);
        if let Some((_, _, staging)) = &queries {
            let b = read_buffer(dev, staging);
            let t: Vec<u64> = bytemuck::pod_collect_to_vec(&b);
            let period = f64::from(dev.queue().get_timestamp_period());
            if run > 0 {
                for k in 0..3 {
                    let ns = t[2 * k + 1].wrapping_sub(t[2 * k]) as f64 * period;
                    best[k] = best[k].min(ns / 1e6);
                }
            }
        }
        if run == 0 {
            let c: Vec<u32> = bytemuck::pod_collect_to_vec(&read_buffer(dev, &counters_staging));
            fragments = [c[0], c[1], c[2]];
        }
    }
    let colour: Vec<[f32; 4]> = read_texture(dev, &resolved, 8)
        .chunks_exact(8)
        .map(|t| {
            let h: [u16; 4] = bytemuck::pod_read_unaligned(t);
            h.map(|x| half::f16::from_bits(x).to_f32())
        })
        .collect();
    let fat = (cfg.storage == Storage::Fat && !ms).then(|| FatGBuffer {
        normal: bytemuck::pod_collect_to_vec(&read_texture(dev, &gtex[0], 16)),
        view_z: bytemuck::pod_collect_to_vec(&read_texture(dev, &gtex[1], 4)),
    });
    let diet = (matches!(cfg.storage, Storage::Diet { .. }) && !ms).then(|| DietGBuffer {
        targets: gtex
            .iter()
            .map(|t| read_texture(dev, t, t.format().block_copy_size(None).unwrap_or(4)))
            .collect(),
        depth: (dformat == wgpu::TextureFormat::Depth32Float).then(|| {
            bytemuck::pod_collect_to_vec(&read_aspect(
                dev,
                &depth,
                4,
                wgpu::TextureAspect::DepthOnly,
            ))
        }),
    });
    let classes = sorted.ranges.clone().map(|r| r.end - r.start);
    Ok(Output {
        width: cfg.width,
        height: cfg.height,
        colour,
        fat,
        diet,
        // Run 0 alone includes lavapipe's lazy shader compilation: untimed.
        pass_ms: (dev.timestamps && cfg.repeats > 0).then_some(best),
        fragments,
        classes,
        skipped: sorted.skipped,
    })
}
