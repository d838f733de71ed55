//! The smallest deferred renderer on prepass, to copy: plain wgpu, headless, one PNG (`cargo
//! run --release --example deferred_minimal -- [OUT.png]`, default target/deferred_minimal.png).
//!
//! Geometry pass: the view-space normal as an oct24 code in `Rgba8Unorm` (a material id in the
//! free alpha) and `Depth32Float` depth, reversed-Z with an infinite far plane. Lighting pass:
//! a full-screen triangle loads both texels, rebuilds the view-space position from depth and
//! the frustum ray, and shades a sun and a point light. The shader is prepass's WGSL for the
//! `Scene` below plus `deferred.wgsl`. The run checks its image, so CI running it proves it.

use prepass::glam::{self, Vec3, vec3};
use prepass::projection::{DepthConvention, Projection};
use prepass::scene::{self, DepthStorage, NormalEncoding, Scene};
use std::f32::consts::{PI, TAU};
use wgpu::util::DeviceExt;

const WIDTH: u32 = 640;
const HEIGHT: u32 = 360;
const FOV_Y: f32 = 50.0 * PI / 180.0;
const NORMAL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
const OUT_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;
const SKY: [f32; 3] = [0.30, 0.50, 0.85]; // linear rgb

/// World-space position, normal, material id: the vertex layout of `geometry_vs`.
type Vertex = [f32; 7];

/// A UV sphere as a triangle list, counter-clockwise seen from outside (wgpu's front face).
fn sphere(out: &mut Vec<Vertex>, centre: Vec3, radius: f32, material: f32) {
    let (stacks, slices) = (48, 96);
    for i in 0..stacks {
        for j in 0..slices {
            for (di, dj) in [(0, 0), (1, 0), (1, 1), (0, 0), (1, 1), (0, 1)] {
                let theta = PI * (i + di) as f32 / stacks as f32;
                let phi = TAU * (j + dj) as f32 / slices as f32;
                let (sin, cos) = theta.sin_cos();
                let n = vec3(sin * phi.cos(), cos, -sin * phi.sin());
                let p = centre + radius * n;
                out.push([p.x, p.y, p.z, n.x, n.y, n.z, material]);
            }
        }
    }
}

/// A square in the y = 0 plane facing +y, 2·half on a side.
fn ground(out: &mut Vec<Vertex>, half: f32, material: f32) {
    for (x, z) in [(-1, -1), (-1, 1), (1, 1), (-1, -1), (1, 1), (1, -1)] {
        let (x, z) = (x as f32 * half, z as f32 * half);
        out.push([x, 0.0, z, 0.0, 1.0, 0.0, material]);
    }
}

fn main() {
    if let Err(e) = run() {
        eprintln!("deferred_minimal: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let default_path = "target/deferred_minimal.png";
    let out_path = std::env::args().nth(1).unwrap_or(default_path.into());

    // The G-buffer choices pick the prepass functions composed in: the oct24 encoder and
    // decoder, the depth-uniform decoder and the frustum-ray position rebuild, nothing else.
    let scene = Scene {
        depth: scene::DepthChoice {
            storage: DepthStorage::Float32,
            convention: DepthConvention::Reversed,
            infinite_far: true,
        },
        normal: scene::NormalChoice {
            encoding: Some(NormalEncoding::Oct24),
            fast_encoder: false,
        },
        position: scene::PositionChoice::View,
        ..Scene::default()
    };
    let source = scene.wgsl()? + include_str!("deferred.wgsl");

    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter =
        pollster::block_on(instance.request_adapter(&Default::default())).map_err(|e| {
            format!("no wgpu adapter ({e}): install Mesa lavapipe (bash .ci/setup-adapter)")
        })?;
    let (device, queue) = pollster::block_on(adapter.request_device(&Default::default()))?;
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("deferred"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });

    // Reversed-Z gives float depth's dense exponents to the far distances where perspective
    // needs them; with the far plane at infinity there is no far distance to tune, no clipping.
    let projection = Projection::new(0.1, f32::INFINITY, DepthConvention::Reversed)?;
    let aspect = WIDTH as f32 / HEIGHT as f32;
    let proj = projection.perspective_rh(FOV_Y, aspect);
    let view =
        glam::camera::rh::view::look_at_mat4(vec3(0.0, 2.0, 6.5), vec3(0.0, 0.8, 0.0), Vec3::Y);
    // Lights go to view space once here, rather than every pixel to world space.
    let sun = view.transform_vector3(vec3(-0.5, 1.0, 0.6).normalize());
    let point = view.transform_point3(vec3(0.2, 1.1, 1.5));
    let up = view.transform_vector3(Vec3::Y);
    // From the matrix itself, so the rays can never disagree with it.
    let [tx, ty] = prepass::position::tan_half_fov_of(proj);
    // `Frame` of deferred.wgsl, field by field (every field 16-byte aligned, so no padding).
    let mut frame = [view.to_cols_array(), proj.to_cols_array()].concat();
    frame.extend(projection.depth_uniform().to_wgsl());
    frame.extend([tx, ty, 0.0, 0.0]);
    frame.extend([sun.x, sun.y, sun.z, 0.0, 1.3, 1.2, 1.05, 0.0]); // direction, colour
    frame.extend([point.x, point.y, point.z, 5.0, 5.0, 2.4, 0.8, 0.0]); // position + radius, colour
    frame.extend([up.x, up.y, up.z, 0.0, SKY[0], SKY[1], SKY[2], 0.0]);

    // Materials: 0 ground, 1 red, 2 blue (deferred.wgsl's ALBEDO).
    let spheres = [(vec3(-1.1, 1.0, 0.0), 1.0), (vec3(1.3, 0.6, 0.9), 0.6)];
    let mut vertices = Vec::new();
    ground(&mut vertices, 500.0, 0.0);
    for (i, &(centre, radius)) in spheres.iter().enumerate() {
        sphere(&mut vertices, centre, radius, 1.0 + i as f32);
    }

    let frame_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("frame"),
        contents: bytemuck::cast_slice(&frame),
        usage: wgpu::BufferUsages::UNIFORM,
    });
    let vertex_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("vertices"),
        contents: bytemuck::cast_slice(&vertices),
        usage: wgpu::BufferUsages::VERTEX,
    });
    let target = |format, usage| {
        let size = wgpu::Extent3d {
            width: WIDTH,
            height: HEIGHT,
            depth_or_array_layers: 1,
        };
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: None,
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage,
            view_formats: &[],
        });
        (texture.create_view(&Default::default()), texture)
    };
    use wgpu::TextureUsages as T;
    let (normal_view, _) = target(NORMAL_FORMAT, T::RENDER_ATTACHMENT | T::TEXTURE_BINDING);
    let (depth_view, _) = target(DEPTH_FORMAT, T::RENDER_ATTACHMENT | T::TEXTURE_BINDING);
    let (out_view, out_tex) = target(OUT_FORMAT, T::RENDER_ATTACHMENT | T::COPY_SRC);

    let buffers = [Some(wgpu::VertexBufferLayout {
        array_stride: size_of::<Vertex>() as u64,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32],
    })];
    let geometry = pipeline(&device, &module, "geometry", &buffers, true, NORMAL_FORMAT);
    let lighting = pipeline(&device, &module, "lighting", &[], false, OUT_FORMAT);
    use wgpu::BindingResource::TextureView as Tex;
    let frame_binding = frame_buf.as_entire_binding();
    let geometry_bind = bind_group(&device, &geometry, [frame_binding.clone()]);
    let lighting_resources = [frame_binding, Tex(&depth_view), Tex(&normal_view)];
    let lighting_bind = bind_group(&device, &lighting, lighting_resources);

    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            color_attachments: &[cleared(&normal_view)],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &depth_view,
                // Reversed-Z with an infinite far plane: depth 0 is infinitely far, the sky.
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(0.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            ..Default::default()
        });
        pass.set_pipeline(&geometry);
        pass.set_bind_group(0, &geometry_bind, &[]);
        pass.set_vertex_buffer(0, vertex_buf.slice(..));
        pass.draw(0..vertices.len() as u32, 0..1);
    }
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            color_attachments: &[cleared(&out_view)],
            ..Default::default()
        });
        pass.set_pipeline(&lighting);
        pass.set_bind_group(0, &lighting_bind, &[]);
        pass.draw(0..3, 0..1);
    }

    // Texture-to-buffer copies need rows padded to 256 bytes.
    let row = WIDTH * 4;
    let padded = row.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: u64::from(padded * HEIGHT),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let copy = wgpu::TexelCopyBufferInfo {
        buffer: &readback,
        layout: wgpu::TexelCopyBufferLayout {
            bytes_per_row: Some(padded),
            ..Default::default()
        },
    };
    encoder.copy_texture_to_buffer(out_tex.as_image_copy(), copy, out_tex.size());
    queue.submit([encoder.finish()]);
    let slice = readback.slice(..);
    slice.map_async(wgpu::MapMode::Read, |r| r.expect("map the readback buffer"));
    device.poll(wgpu::PollType::wait_indefinitely())?;
    let mapped = slice.get_mapped_range()?;
    let rows = mapped.chunks_exact(padded as usize);
    let pixels: Vec<u8> = rows.flat_map(|r| &r[..row as usize]).copied().collect();

    if let Some(dir) = std::path::Path::new(&out_path).parent() {
        std::fs::create_dir_all(dir)?;
    }
    let file = std::fs::File::create(&out_path).map_err(|e| format!("{out_path}: {e}"))?;
    let mut png = png::Encoder::new(std::io::BufWriter::new(file), WIDTH, HEIGHT);
    png.set_color(png::ColorType::Rgba);
    png.write_header()?.write_image_data(&pixels)?;

    // Self-check: the sky where nothing was drawn, light at each sphere's centre.
    let at = |x: u32, y: u32| &pixels[((y * WIDTH + x) * 4) as usize..][..3];
    // The sky as the sRGB target stores it (each channel above sRGB's linear toe).
    let sky = SKY.map(|l| ((1.055 * l.powf(1.0 / 2.4) - 0.055) * 255.0).round() as u8);
    let is_sky = |c: &[u8]| c.iter().zip(sky).all(|(&a, b)| a.abs_diff(b) <= 1);
    if !is_sky(at(0, 0)) {
        return Err(format!("top-left pixel {:?} is not the sky {sky:?}", at(0, 0)).into());
    }
    for (centre, _) in spheres {
        let clip = proj * view * centre.extend(1.0);
        let x = ((clip.x / clip.w + 1.0) * 0.5 * WIDTH as f32) as u32;
        let y = ((1.0 - clip.y / clip.w) * 0.5 * HEIGHT as f32) as u32;
        let c = at(x, y);
        if is_sky(c) || c.iter().map(|&v| u32::from(v)).sum::<u32>() < 60 {
            return Err(format!("sphere centre ({x}, {y}) is {c:?}: not lit").into());
        }
    }
    let lit = pixels.chunks_exact(4).filter(|p| !is_sky(p)).count();
    let info = adapter.get_info();
    let adapter = format!("{} on {:?}", info.name, info.backend);
    println!("{out_path}: {WIDTH}x{HEIGHT}, {lit} lit pixels ({adapter})");
    Ok(())
}

/// A pipeline from the entry points `{name}_vs` and `{name}_fs`, with a depth test or none; its
/// bind group layout is derived from the shader (`layout: None`).
fn pipeline(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    name: &str,
    buffers: &[Option<wgpu::VertexBufferLayout>],
    depth: bool,
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    let depth_stencil = depth.then(|| wgpu::DepthStencilState {
        format: DEPTH_FORMAT,
        depth_write_enabled: Some(true),
        depth_compare: Some(wgpu::CompareFunction::Greater), // reversed-Z: nearer is larger
        stencil: Default::default(),
        bias: Default::default(),
    });
    let (vs, fs) = (format!("{name}_vs"), format!("{name}_fs"));
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(name),
        layout: None,
        vertex: wgpu::VertexState {
            module,
            entry_point: Some(&vs),
            compilation_options: Default::default(),
            buffers,
        },
        primitive: wgpu::PrimitiveState {
            cull_mode: Some(wgpu::Face::Back),
            ..Default::default()
        },
        depth_stencil,
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(&fs),
            compilation_options: Default::default(),
            targets: &[Some(format.into())],
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// Group 0 of `pipeline` with `resources` at bindings 0, 1, 2, …
fn bind_group<'a>(
    device: &wgpu::Device,
    pipeline: &wgpu::RenderPipeline,
    resources: impl IntoIterator<Item = wgpu::BindingResource<'a>>,
) -> wgpu::BindGroup {
    let entries: Vec<_> = (0..)
        .zip(resources)
        .map(|(binding, resource)| wgpu::BindGroupEntry { binding, resource })
        .collect();
    let layout = &pipeline.get_bind_group_layout(0);
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout,
        entries: &entries,
    })
}

/// A colour attachment cleared to zero and stored (`Operations::default()`).
fn cleared(view: &wgpu::TextureView) -> Option<wgpu::RenderPassColorAttachment<'_>> {
    Some(wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: None,
        ops: Default::default(),
    })
}
