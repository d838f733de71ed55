//! Run any WGSL function over a batch of arguments on a real adapter (feature `harness`).
//!
//! Give it WGSL source and a function name: it reads the signature with naga (scalars and
//! vectors of `f32`/`u32`/`i32`), appends a generated compute entry point that applies the
//! function to every element, and runs it through wgpu — on the GPU where there is one, on Mesa's
//! lavapipe (a Vulkan driver on the CPU) where there is not. Batches of any size run in chunked
//! dispatches; [`Kernel::run_chunks`] streams results so sweeps of 2^32 inputs fit in memory.
//!
//! ```no_run
//! use prepass::harness::{Arg, Gpu};
//! let gpu = Gpu::new()?; // fails with the fix in its message when no adapter exists
//! println!("adapter: {}", gpu.describe());
//! let kernel = gpu.kernel(prepass::wgsl::DEPTH24, "hyperbolic_depth_from_depth24")?;
//! let out = kernel.run(&[Arg::Index { start: 0 }], 1 << 24)?; // every 24-bit code
//! assert_eq!(out.as_f32()[(1 << 24) - 1], 1.0);
//! # Ok::<(), prepass::harness::HarnessError>(())
//! ```

mod codegen;
mod signature;
mod timing;

pub use codegen::{Feed, TimedBody, WORKGROUP_SIZE};
pub use signature::{Param, Scalar, Signature, SignatureError, ValueType};
pub use timing::{DEFAULT_TIMING_TILE, MIN_TIMED_INVOCATIONS, Timing, TimingMethod};

use crate::wgsl::parse_and_validate;
use std::sync::Mutex;
use wgpu::util::DeviceExt as _;

/// How to get an adapter on a machine without one; part of every no-adapter error.
pub const NO_ADAPTER_FIX: &str = "install a Vulkan driver — on a machine without a GPU, Mesa's \
     software driver lavapipe: `sudo apt-get update && sudo apt-get install -y \
     mesa-vulkan-drivers libvulkan1` (Debian/Ubuntu; `.ci/setup-adapter` does this) — or run on \
     a machine with a Vulkan, Metal or Direct3D 12 GPU. WGPU_BACKEND and PREPASS_ADAPTER \
     (a substring of the adapter name) choose among several";

/// Everything that can stop a harness run.
#[derive(Debug)]
pub enum HarnessError {
    /// No adapter could be found; the message says how to get one.
    NoAdapter {
        /// What was looked for and what was found.
        detail: String,
    },
    /// The adapter refused a device.
    Device(String),
    /// The function's signature cannot be run.
    Signature(SignatureError),
    /// The generated module failed naga or wgpu validation.
    Shader(String),
    /// The arguments do not fit the signature.
    Arguments(String),
    /// Reading results back failed.
    Readback(String),
}

impl std::fmt::Display for HarnessError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NoAdapter { detail } => {
                write!(
                    f,
                    "no wgpu adapter to run WGSL on ({detail}). Fix: {NO_ADAPTER_FIX}."
                )
            }
            Self::Device(m) => write!(f, "the adapter refused a device: {m}"),
            Self::Signature(e) => e.fmt(f),
            Self::Shader(m) => write!(f, "the generated shader is invalid: {m}"),
            Self::Arguments(m) => write!(f, "arguments do not fit the signature: {m}"),
            Self::Readback(m) => write!(f, "reading results back failed: {m}"),
        }
    }
}

impl std::error::Error for HarnessError {}

impl From<SignatureError> for HarnessError {
    fn from(e: SignatureError) -> Self {
        Self::Signature(e)
    }
}

/// An adapter and a device on it.
pub struct Gpu {
    adapter: wgpu::Adapter,
    device: wgpu::Device,
    queue: wgpu::Queue,
    /// Every pipeline built on this device, by its full WGSL: a kernel another test (or another
    /// policy served by the same module) already compiled is not compiled again. On a CPU
    /// adapter compilation costs far more than running.
    pipelines: Mutex<std::collections::HashMap<String, wgpu::ComputePipeline>>,
    /// Buffers of finished runs, oldest first, for the next run that needs one of the same
    /// usage and size ([`Gpu::take_buffer`]).
    buffers: Mutex<Vec<wgpu::Buffer>>,
}

/// At most this many bytes of buffers wait in [`Gpu`]'s pool for reuse (oldest given up
/// first): a sweep of 2^24 elements runs in chunks of [`MAX_CHUNK`], each chunk's column,
/// output and readback buffers up to 64 MiB.
const POOL_BYTES: u64 = 512 << 20;

fn device_rank(t: wgpu::DeviceType) -> u8 {
    match t {
        wgpu::DeviceType::DiscreteGpu => 0,
        wgpu::DeviceType::IntegratedGpu => 1,
        wgpu::DeviceType::VirtualGpu => 2,
        wgpu::DeviceType::Cpu => 3,
        wgpu::DeviceType::Other => 4,
    }
}

impl Gpu {
    /// Open the best adapter: a discrete GPU before an integrated, virtual or software one, on
    /// Vulkan, Metal or Direct3D 12. `WGPU_BACKEND` (e.g. `vulkan`, or `gl` for wgpu's GL
    /// backend: naga's GLSL path, as WebGL2 and GLES users get it) chooses the backends tried
    /// instead, `PREPASS_ADAPTER` picks the first adapter whose name contains it
    /// (case-insensitive).
    ///
    /// With no adapter it returns [`HarnessError::NoAdapter`], whose message names the fix.
    pub fn new() -> Result<Self, HarnessError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        // GL only when asked for: on a machine with Mesa, llvmpipe's GL would otherwise stand
        // beside lavapipe's Vulkan as a second software adapter.
        let backends = wgpu::Backends::from_env().unwrap_or(wgpu::Backends::PRIMARY);
        let mut adapters = pollster::block_on(instance.enumerate_adapters(backends));
        let wanted = std::env::var("PREPASS_ADAPTER")
            .ok()
            .map(|s| s.to_lowercase());
        let seen: Vec<String> = adapters
            .iter()
            .map(|a| {
                let i = a.get_info();
                format!("{} ({:?})", i.name, i.backend)
            })
            .collect();
        if let Some(w) = &wanted {
            adapters.retain(|a| a.get_info().name.to_lowercase().contains(w));
        }
        adapters.sort_by_key(|a| device_rank(a.get_info().device_type));
        let Some(adapter) = adapters.into_iter().next() else {
            let detail = match wanted {
                Some(w) => format!(
                    "PREPASS_ADAPTER={w:?} matches none of the adapters found: [{}]",
                    seen.join(", ")
                ),
                None => format!("backends tried: {backends:?}; none found"),
            };
            return Err(HarnessError::NoAdapter { detail });
        };
        // Optional features, on where the adapter has them: timestamp queries (timed
        // dispatches, render-pass times) and the adapter's own texture-format capabilities
        // (multisample counts beyond WebGPU's guaranteed ones, for renderers on this device).
        let required_features = adapter.features()
            & (wgpu::Features::TIMESTAMP_QUERY
                | wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES);
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("prepass harness"),
            required_features,
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .map_err(|e| HarnessError::Device(e.to_string()))?;
        Ok(Gpu {
            adapter,
            device,
            queue,
            pipelines: Mutex::new(std::collections::HashMap::new()),
            buffers: Mutex::new(Vec::new()),
        })
    }

    /// A buffer of `size` bytes (at least 4) and `usage`: one a finished run gave back
    /// ([`Gpu::give_back`]), or a new one. Why keep them: a new buffer's memory is fresh pages
    /// the kernel faults in and zeroes on first touch, and a sweep runs the same sizes again
    /// and again (measured on lavapipe, 2026-12-05: ten runs of `x * 2.0` over 2^24 floats
    /// took 2.47 s with new buffers per run).
    fn take_buffer(&self, size: u64, usage: wgpu::BufferUsages, label: &str) -> wgpu::Buffer {
        let size = size.max(4);
        {
            let mut pool = self.buffers.lock().unwrap_or_else(|p| p.into_inner());
            if let Some(k) = pool
                .iter()
                .position(|b| b.size() == size && b.usage() == usage)
            {
                return pool.remove(k);
            }
        }
        self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size,
            usage,
            mapped_at_creation: false,
        })
    }

    /// Keep `buffers` (unmapped, no longer in use) for [`Gpu::take_buffer`], within
    /// [`POOL_BYTES`].
    fn give_back(&self, buffers: impl IntoIterator<Item = wgpu::Buffer>) {
        let mut pool = self.buffers.lock().unwrap_or_else(|p| p.into_inner());
        pool.extend(buffers);
        let mut bytes: u64 = pool.iter().map(wgpu::Buffer::size).sum();
        while bytes > POOL_BYTES {
            bytes -= pool.remove(0).size();
        }
    }

    /// The adapter the device was opened on.
    pub fn adapter(&self) -> &wgpu::Adapter {
        &self.adapter
    }

    /// The adapter's own description (name, backend, driver).
    pub fn adapter_info(&self) -> wgpu::AdapterInfo {
        self.adapter.get_info()
    }

    /// One line naming the adapter, its kind, backend and driver — for reports.
    pub fn describe(&self) -> String {
        let i = self.adapter.get_info();
        format!(
            "{} [{:?}, {:?}, driver {} {}]",
            i.name, i.device_type, i.backend, i.driver, i.driver_info
        )
    }

    /// Whether the adapter is a software rasteriser (lavapipe, WARP, SwiftShader): its timings
    /// measure a CPU, not a GPU.
    pub fn is_software(&self) -> bool {
        self.adapter.get_info().device_type == wgpu::DeviceType::Cpu
    }

    /// The wgpu device, for callers who need more than the harness.
    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    /// The wgpu queue.
    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// Run a [`Dispatch`] (from [`Kernel::dispatch`], on this or another `Gpu`) here, as another
    /// WebGPU implementation would run it: its module as it stands, its buffers, its grid.
    pub fn run_dispatch(&self, d: &Dispatch) -> Result<Output, HarnessError> {
        parse_and_validate(&d.source).map_err(|e| HarnessError::Shader(e.to_string()))?;
        let device = &self.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("prepass dispatch"),
            source: wgpu::ShaderSource::Wgsl(d.source.as_str().into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("prepass dispatch"),
            layout: None,
            module: &module,
            entry_point: Some(d.entry),
            compilation_options: Default::default(),
            cache: None,
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(HarnessError::Shader(e.to_string()));
        }
        let init = |bytes: &[u8], usage: wgpu::BufferUsages| {
            let mut padded = bytes.to_vec();
            padded.resize(bytes.len().max(16).next_multiple_of(16), 0);
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("prepass dispatch"),
                contents: &padded,
                usage,
            })
        };
        let params = init(
            bytemuck::cast_slice(&d.uniform),
            wgpu::BufferUsages::UNIFORM,
        );
        let columns: Vec<wgpu::Buffer> = d
            .columns
            .iter()
            .map(|c| init(c, wgpu::BufferUsages::STORAGE))
            .collect();
        let bytes = (d.output_words() as u64 * 4).max(16);
        let make = |usage| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("prepass dispatch"),
                size: bytes,
                usage,
                mapped_at_creation: false,
            })
        };
        let out = make(wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC);
        let staging = make(wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST);
        let group = bind_group(
            device,
            &pipeline,
            &params,
            columns.iter(),
            &out,
            "prepass dispatch",
        );
        let mut encoder =
            device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &group, &[]);
            pass.dispatch_workgroups(d.groups[0], d.groups[1], 1);
        }
        encoder.copy_buffer_to_buffer(&out, 0, &staging, 0, bytes);
        self.queue.submit([encoder.finish()]);
        let mut words = read_back(self, &staging, bytes)?;
        words.truncate(d.output_words());
        d.output(words)
    }

    /// Prepare `function` from `source` (which must be valid WGSL on its own) to run on batches.
    pub fn kernel(&self, source: &str, function: &str) -> Result<Kernel<'_>, HarnessError> {
        self.kernel_with_tail(source, function, &[])
    }

    /// [`Gpu::kernel`] with tail words: after the call, each `u32` WGSL expression of `tail`
    /// (typically a `var<private>` the function sets) is stored per element after the result's
    /// words; [`Kernel::run_with_tail`] returns them. A function and a flag it raises then
    /// come from one pipeline, where a second function returning the flag would compile the
    /// whole evaluation again.
    pub fn kernel_with_tail(
        &self,
        source: &str,
        function: &str,
        tail: &[String],
    ) -> Result<Kernel<'_>, HarnessError> {
        let signature = Signature::read(source, function)?;
        Ok(Kernel {
            gpu: self,
            source: source.to_string(),
            signature,
            tail: tail.to_vec(),
            pipelines: Mutex::new(Vec::new()),
        })
    }
}

/// One argument of a batch run.
#[derive(Clone, Copy, Debug)]
pub enum Arg<'a> {
    /// One value per element, as raw bytes (`n × words × 4` of them); see [`Arg::column`].
    Column(&'a [u8]),
    /// One value for every element, passed in a uniform buffer as a renderer passes uniforms.
    /// Holds the value's bits, lanes in order; unused lanes are ignored.
    Splat([u32; 4]),
    /// Element `i` receives the bits `start + i` (wrapping), read as the parameter's scalar
    /// type: every 24-bit code, or every `f32` bit pattern in a range, without uploading them.
    /// Scalar parameters only.
    Index {
        /// Bits given to element 0.
        start: u32,
    },
}

impl<'a> Arg<'a> {
    /// A column from any plain-old-data slice: `&[f32]`, `&[u32]`, `&[[f32; 3]]`, `&[glam::Vec3]`…
    pub fn column<T: bytemuck::NoUninit>(values: &'a [T]) -> Self {
        Arg::Column(bytemuck::cast_slice(values))
    }

    /// The same `f32` for every element.
    pub fn splat_f32(x: f32) -> Self {
        Arg::Splat([x.to_bits(), 0, 0, 0])
    }

    /// The same `u32` for every element.
    pub fn splat_u32(x: u32) -> Self {
        Arg::Splat([x, 0, 0, 0])
    }

    /// The same vector for every element (up to 4 `f32` lanes).
    pub fn splat_vec(lanes: &[f32]) -> Self {
        let mut w = [0u32; 4];
        for (slot, x) in w.iter_mut().zip(lanes) {
            *slot = x.to_bits();
        }
        Arg::Splat(w)
    }

    fn feed(&self) -> Feed {
        match self {
            Arg::Column(_) => Feed::Column,
            Arg::Splat(_) => Feed::Splat,
            Arg::Index { .. } => Feed::Index,
        }
    }
}

/// The results of a run (or of one chunk of it): `len` values of type `ty`, as raw words.
#[derive(Clone, Debug, PartialEq)]
pub struct Output {
    /// Type of each value.
    pub ty: ValueType,
    words: Vec<u32>,
}

impl Output {
    /// Results of type `ty`, their words in order (runs put together from parts).
    pub(crate) fn from_words(ty: ValueType, words: Vec<u32>) -> Self {
        Output { ty, words }
    }

    /// Number of values.
    pub fn len(&self) -> usize {
        self.words.len() / self.ty.words()
    }

    /// Whether there are no values.
    pub fn is_empty(&self) -> bool {
        self.words.is_empty()
    }

    /// The raw 32-bit words, lanes of each value consecutive.
    pub fn words(&self) -> &[u32] {
        &self.words
    }

    /// Take the raw words.
    pub fn into_words(self) -> Vec<u32> {
        self.words
    }

    /// Scalar `f32` results (or the lanes of vectors, flattened).
    pub fn as_f32(&self) -> &[f32] {
        bytemuck::cast_slice(&self.words)
    }

    /// Take the scalar `f32` results (or lanes) without copying them: the words' allocation is
    /// reused (a sweep's 2^24 results are 64 MiB, and a fresh copy costs its page faults).
    pub fn into_f32(self) -> Vec<f32> {
        self.words.into_iter().map(f32::from_bits).collect()
    }

    /// Scalar `u32` results (or lanes).
    pub fn as_u32(&self) -> &[u32] {
        &self.words
    }

    /// Scalar `i32` results (or lanes).
    pub fn as_i32(&self) -> &[i32] {
        bytemuck::cast_slice(&self.words)
    }

    /// `vec2<f32>` results. Panics if the result is not two lanes wide.
    pub fn as_vec2(&self) -> &[[f32; 2]] {
        assert_eq!(self.ty.lanes, 2, "result is {}", self.ty);
        bytemuck::cast_slice(&self.words)
    }

    /// `vec3<f32>` results. Panics if the result is not three lanes wide.
    pub fn as_vec3(&self) -> &[[f32; 3]] {
        assert_eq!(self.ty.lanes, 3, "result is {}", self.ty);
        bytemuck::cast_slice(&self.words)
    }

    /// `vec4<f32>` results. Panics if the result is not four lanes wide.
    pub fn as_vec4(&self) -> &[[f32; 4]] {
        assert_eq!(self.ty.lanes, 4, "result is {}", self.ty);
        bytemuck::cast_slice(&self.words)
    }
}

/// A function prepared to run on batches; pipelines are compiled once per pattern of feeds.
pub struct Kernel<'g> {
    gpu: &'g Gpu,
    source: String,
    signature: Signature,
    tail: Vec<String>,
    pipelines: Mutex<Vec<(Vec<Feed>, wgpu::ComputePipeline)>>,
}

/// Largest number of elements per dispatch: bounds the buffers (a `vec4` column chunk is
/// 64 MiB) while keeping dispatch overhead negligible.
pub const MAX_CHUNK: u64 = 1 << 22;

impl Kernel<'_> {
    /// The function's signature as naga read it.
    pub fn signature(&self) -> &Signature {
        &self.signature
    }

    /// The full WGSL that runs for these arguments: the source plus the generated entry point.
    pub fn generated_source(&self, args: &[Arg<'_>]) -> String {
        let feeds: Vec<Feed> = args.iter().map(Arg::feed).collect();
        format!(
            "{}\n\n// ---- generated by prepass::harness ----\n{}",
            self.source,
            codegen::entry_point_with_tail(&self.signature, &feeds, &self.tail)
        )
    }

    /// Words per element after the result ([`Gpu::kernel_with_tail`]); 0 for a plain kernel.
    pub fn tail_words(&self) -> usize {
        self.tail.len()
    }

    /// An error unless `args` has one entry per parameter of the function.
    fn check_arity(&self, args: &[Arg<'_>]) -> Result<(), HarnessError> {
        let sig = &self.signature;
        if args.len() == sig.params.len() {
            return Ok(());
        }
        Err(HarnessError::Arguments(format!(
            "`{}` takes {} arguments, {} given",
            sig.function,
            sig.params.len(),
            args.len()
        )))
    }

    /// An error unless `args` fit the signature for `n` elements: one per parameter, each
    /// column `n` values long, index feeds on scalars only.
    fn check_args(&self, args: &[Arg<'_>], n: u64) -> Result<(), HarnessError> {
        let sig = &self.signature;
        self.check_arity(args)?;
        for (p, a) in sig.params.iter().zip(args) {
            match a {
                Arg::Column(bytes) => {
                    let want = n.checked_mul(p.ty.words() as u64 * 4);
                    if want != Some(bytes.len() as u64) {
                        return Err(HarnessError::Arguments(format!(
                            "column for `{}: {}` holds {} bytes; {n} elements need {}",
                            p.name,
                            p.ty,
                            bytes.len(),
                            n * p.ty.words() as u64 * 4
                        )));
                    }
                }
                Arg::Index { .. } if p.ty.lanes != 1 => {
                    return Err(HarnessError::Arguments(format!(
                        "Arg::Index feeds scalars; `{}` is {}",
                        p.name, p.ty
                    )));
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// Apply the function to `n` elements and return all results.
    pub fn run(&self, args: &[Arg<'_>], n: u64) -> Result<Output, HarnessError> {
        Ok(self.run_with_tail(args, n)?.0)
    }

    /// [`Kernel::run`], and the tail words ([`Gpu::kernel_with_tail`]): `n ×`
    /// [`Kernel::tail_words`] of them, element by element (empty for a plain kernel).
    pub fn run_with_tail(
        &self,
        args: &[Arg<'_>],
        n: u64,
    ) -> Result<(Output, Vec<u32>), HarnessError> {
        self.run_with_tail_prefix(args, n, self.tail.len())
    }

    /// [`Kernel::run_with_tail`] keeping only the first `keep` tail words of each element
    /// (`n × keep` of them): a caller that reads the rest only sometimes keeps one pipeline
    /// without holding every element's words.
    pub fn run_with_tail_prefix(
        &self,
        args: &[Arg<'_>],
        n: u64,
        keep: usize,
    ) -> Result<(Output, Vec<u32>), HarnessError> {
        let total = usize::try_from(n)
            .ok()
            .and_then(|n| n.checked_mul(self.signature.result.words()))
            .ok_or_else(|| HarnessError::Arguments(format!("{n} results do not fit in memory")))?;
        let (w, t) = (self.signature.result.words(), self.tail.len());
        let keep = keep.min(t);
        let mut words = Vec::with_capacity(total);
        let mut tail = Vec::with_capacity(n as usize * keep);
        self.run_chunks_raw(args, n, |_, chunk| {
            if t == 0 {
                words.extend_from_slice(chunk);
                return Ok(());
            }
            for e in chunk.chunks_exact(w + t) {
                words.extend_from_slice(&e[..w]);
                tail.extend_from_slice(&e[w..w + keep]);
            }
            Ok(())
        })?;
        let out = Output {
            ty: self.signature.result,
            words,
        };
        Ok((out, tail))
    }

    /// Apply the function to `n` elements, handing each chunk's results to `each(first, chunk)`
    /// as soon as it is read back (`first` = index of the chunk's first element). Memory stays
    /// bounded by one chunk whatever `n` is. An error from `each` stops the run.
    pub fn run_chunks(
        &self,
        args: &[Arg<'_>],
        n: u64,
        mut each: impl FnMut(u64, &Output) -> Result<(), HarnessError>,
    ) -> Result<(), HarnessError> {
        let (w, t) = (self.signature.result.words(), self.tail.len());
        self.run_chunks_raw(args, n, |first, chunk| {
            let words = if t == 0 {
                chunk.to_vec()
            } else {
                chunk
                    .chunks_exact(w + t)
                    .flat_map(|e| e[..w].iter().copied())
                    .collect()
            };
            let out = Output {
                ty: self.signature.result,
                words,
            };
            each(first, &out)
        })
    }

    /// [`Kernel::run_chunks`], each chunk's words as the shader wrote them (per element, the
    /// result's words, then the tail's), read from the mapped readback buffer.
    fn run_chunks_raw(
        &self,
        args: &[Arg<'_>],
        n: u64,
        mut each: impl FnMut(u64, &[u32]) -> Result<(), HarnessError>,
    ) -> Result<(), HarnessError> {
        let sig = &self.signature;
        self.check_args(args, n)?;
        if n == 0 {
            return Ok(());
        }
        let pipeline = self.pipeline(args)?;
        let gpu = self.gpu;
        let limits = gpu.device.limits();
        let widest = sig
            .params
            .iter()
            .map(|p| p.ty.words())
            .chain([sig.result.words() + self.tail.len()])
            .max()
            .unwrap_or(1) as u64;
        let binding_limit = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        let per_dim = u64::from(limits.max_compute_workgroups_per_dimension);
        let wg = u64::from(WORKGROUP_SIZE);
        let chunk = MAX_CHUNK
            .min(binding_limit / (widest * 4))
            .min(per_dim * per_dim * wg)
            .min(n)
            / wg
            * wg;
        let chunk = chunk.max(wg.min(n));

        // Each column: the storage buffer the shader reads, and the mappable buffer its chunks
        // are written into and copied from (the queue's own write would stage each chunk in
        // a new allocation).
        let columns: Vec<(usize, wgpu::Buffer, wgpu::Buffer, u64)> = args
            .iter()
            .enumerate()
            .filter(|(_, a)| matches!(a, Arg::Column(_)))
            .map(|(k, _)| {
                let stride = sig.params[k].ty.words() as u64 * 4;
                let usage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST;
                let upload = wgpu::BufferUsages::MAP_WRITE | wgpu::BufferUsages::COPY_SRC;
                (
                    k,
                    gpu.take_buffer(chunk * stride, usage, "prepass column"),
                    gpu.take_buffer(chunk * stride, upload, "prepass upload"),
                    stride,
                )
            })
            .collect();
        let (w, t) = (sig.result.words(), self.tail.len());
        let out_stride = (w + t) as u64 * 4;
        let out = gpu.take_buffer(
            chunk * out_stride,
            wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            "prepass output",
        );
        let staging = gpu.take_buffer(
            chunk * out_stride,
            wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            "prepass readback",
        );
        let params = gpu
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("prepass params"),
                contents: &vec![0u8; codegen::uniform_words(args.len()) * 4],
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            });
        let bind_group = bind_group(
            &gpu.device,
            &pipeline,
            &params,
            columns.iter().map(|(_, buf, _, _)| buf),
            &out,
            "prepass harness",
        );

        let mut first = 0u64;
        while first < n {
            let count = chunk.min(n - first);
            let groups = count.div_ceil(wg);
            let gx = groups.min(per_dim);
            let gy = groups.div_ceil(gx);
            let uniform = chunk_uniform(args, first, count, gx * wg);
            gpu.queue
                .write_buffer(&params, 0, bytemuck::cast_slice(&uniform));
            let mut encoder = gpu
                .device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
            for (k, buf, upload, stride) in &columns {
                let Arg::Column(bytes) = args[*k] else {
                    unreachable!("columns are built from Column args")
                };
                let lo = (first * stride) as usize;
                let hi = ((first + count) * stride) as usize;
                write_mapped(gpu, upload, &bytes[lo..hi])?;
                encoder.copy_buffer_to_buffer(upload, 0, buf, 0, count * stride);
            }
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
                pass.set_pipeline(&pipeline);
                pass.set_bind_group(0, &bind_group, &[]);
                pass.dispatch_workgroups(gx as u32, gy as u32, 1);
            }
            let bytes = count * out_stride;
            encoder.copy_buffer_to_buffer(&out, 0, &staging, 0, bytes);
            gpu.queue.submit([encoder.finish()]);
            read_back_with(gpu, &staging, bytes, |words| each(first, words))??;
            first += count;
        }
        let inputs = columns
            .into_iter()
            .flat_map(|(_, buf, upload, _)| [buf, upload]);
        gpu.give_back(inputs.chain([out, staging]));
        Ok(())
    }

    /// The single dispatch that applies the function to `n ≤ MAX_CHUNK` elements, described for
    /// another WebGPU implementation to run (e.g. Dawn, with Tint as its compiler, through
    /// node): the module with its generated entry point, the uniform and column buffers in
    /// binding order, and the workgroup grid. Its results read back through
    /// [`Dispatch::output`] into the same [`Output`] a [`Kernel::run`] gives, so figures from
    /// either implementation compare directly. The module is validated by naga first.
    pub fn dispatch(&self, args: &[Arg<'_>], n: u64) -> Result<Dispatch, HarnessError> {
        self.check_args(args, n)?;
        if !self.tail.is_empty() {
            return Err(HarnessError::Arguments(
                "a kernel with tail words runs through Kernel::run_with_tail only".into(),
            ));
        }
        if n == 0 || n > MAX_CHUNK {
            return Err(HarnessError::Arguments(format!(
                "a Dispatch holds 1 to {MAX_CHUNK} elements, not {n}"
            )));
        }
        let columns = args
            .iter()
            .filter_map(|a| match a {
                Arg::Column(bytes) => Some(bytes.to_vec()),
                _ => None,
            })
            .collect();
        let sig = &self.signature;
        let source = self.generated_source(args);
        parse_and_validate(&source).map_err(|e| HarnessError::Shader(e.to_string()))?;
        // WebGPU's guaranteed limit of workgroups per dimension.
        let wg = u64::from(WORKGROUP_SIZE);
        let groups = n.div_ceil(wg);
        let gx = groups.min(65_535);
        let gy = groups.div_ceil(gx);
        Ok(Dispatch {
            source,
            entry: codegen::ENTRY,
            uniform: chunk_uniform(args, 0, n, gx * wg),
            columns,
            groups: [gx as u32, gy as u32],
            count: n,
            result: sig.result,
        })
    }

    fn pipeline(&self, args: &[Arg<'_>]) -> Result<wgpu::ComputePipeline, HarnessError> {
        let feeds: Vec<Feed> = args.iter().map(Arg::feed).collect();
        let mut cache = self.pipelines.lock().unwrap_or_else(|p| p.into_inner());
        if let Some((_, p)) = cache.iter().find(|(f, _)| *f == feeds) {
            return Ok(p.clone());
        }
        let source = self.generated_source(args);
        let pipeline = self.compile(&source, &self.signature.function)?;
        cache.push((feeds, pipeline.clone()));
        Ok(pipeline)
    }

    /// Validate `source` with naga, then build its generated entry point as a compute pipeline
    /// (or take the one this device already built from the same text).
    fn compile(&self, source: &str, label: &str) -> Result<wgpu::ComputePipeline, HarnessError> {
        let built = |cache: &std::collections::HashMap<_, wgpu::ComputePipeline>| {
            cache.get(source).cloned()
        };
        let lock = || self.gpu.pipelines.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(p) = built(&lock()) {
            return Ok(p);
        }
        let pipeline = self.build(source, label)?;
        lock().insert(source.to_string(), pipeline.clone());
        Ok(pipeline)
    }

    fn build(&self, source: &str, label: &str) -> Result<wgpu::ComputePipeline, HarnessError> {
        // naga first: its messages point at the offending line, and wgpu would otherwise panic.
        parse_and_validate(source).map_err(|e| HarnessError::Shader(e.to_string()))?;
        let device = &self.gpu.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(label),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(label),
            layout: None,
            module: &module,
            entry_point: Some(codegen::ENTRY),
            compilation_options: Default::default(),
            cache: None,
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(HarnessError::Shader(e.to_string()));
        }
        Ok(pipeline)
    }
}

/// The uniform words of one chunk (`codegen::uniform_words` layout): count, row stride, two pad
/// words, then one slot per argument (a splat's value, an index feed's start for this chunk).
fn chunk_uniform(args: &[Arg<'_>], first: u64, count: u64, row_stride: u64) -> Vec<u32> {
    let mut uniform = vec![count as u32, row_stride as u32, 0, 0];
    for a in args {
        uniform.extend_from_slice(&match *a {
            Arg::Splat(v) => v,
            Arg::Index { start } => [start.wrapping_add(first as u32), 0, 0, 0],
            Arg::Column(_) => [0; 4],
        });
    }
    if args.is_empty() {
        uniform.extend_from_slice(&[0; 4]);
    }
    uniform
}

/// One dispatch of a [`Kernel`], self-contained, for a WebGPU implementation other than wgpu
/// (see [`Kernel::dispatch`]). Bind group 0: binding 0 the uniform buffer (`uniform`), bindings
/// 1… the storage buffers of `columns` in order, the last binding the output buffer of
/// `count × result.words()` words; dispatch `groups[0] × groups[1]` workgroups of
/// [`WORKGROUP_SIZE`] on entry point `entry`.
#[derive(Clone, Debug)]
pub struct Dispatch {
    /// The function's source with the generated entry point appended.
    pub source: String,
    /// The entry point's name.
    pub entry: &'static str,
    /// The uniform buffer's words.
    pub uniform: Vec<u32>,
    /// Each column's bytes, in binding order.
    pub columns: Vec<Vec<u8>>,
    /// Workgroups in x and y.
    pub groups: [u32; 2],
    /// Elements.
    pub count: u64,
    /// Type of each result.
    pub result: ValueType,
}

impl Dispatch {
    /// Words the output buffer holds.
    pub fn output_words(&self) -> usize {
        self.count as usize * self.result.words()
    }

    /// The results another implementation read back, as the harness's [`Output`]; an error
    /// unless there are exactly [`Dispatch::output_words`] of them.
    pub fn output(&self, words: Vec<u32>) -> Result<Output, HarnessError> {
        if words.len() != self.output_words() {
            return Err(HarnessError::Readback(format!(
                "{} words read back, {} expected",
                words.len(),
                self.output_words()
            )));
        }
        Ok(Output {
            ty: self.result,
            words,
        })
    }
}

/// The harness's bind group 0: uniforms at binding 0, the column buffers from binding 1 in
/// parameter order, the output buffer last (the layout `codegen` declares).
pub(crate) fn bind_group<'b>(
    device: &wgpu::Device,
    pipeline: &wgpu::ComputePipeline,
    params: &wgpu::Buffer,
    columns: impl Iterator<Item = &'b wgpu::Buffer>,
    out: &wgpu::Buffer,
    label: &str,
) -> wgpu::BindGroup {
    let mut entries = vec![wgpu::BindGroupEntry {
        binding: 0,
        resource: params.as_entire_binding(),
    }];
    for buf in columns {
        entries.push(wgpu::BindGroupEntry {
            binding: entries.len() as u32,
            resource: buf.as_entire_binding(),
        });
    }
    entries.push(wgpu::BindGroupEntry {
        binding: entries.len() as u32,
        resource: out.as_entire_binding(),
    });
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some(label),
        layout: &pipeline.get_bind_group_layout(0),
        entries: &entries,
    })
}

fn read_back(gpu: &Gpu, staging: &wgpu::Buffer, bytes: u64) -> Result<Vec<u32>, HarnessError> {
    read_back_with(gpu, staging, bytes, <[u32]>::to_vec)
}

/// Map `slice` for `mode` and wait until it is mapped.
fn map(gpu: &Gpu, slice: &wgpu::BufferSlice<'_>, mode: wgpu::MapMode) -> Result<(), HarnessError> {
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(mode, move |r| {
        let _ = tx.send(r);
    });
    gpu.device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| HarnessError::Readback(e.to_string()))?;
    rx.recv()
        .map_err(|e| HarnessError::Readback(e.to_string()))?
        .map_err(|e| HarnessError::Readback(e.to_string()))
}

/// `bytes` written at the start of `upload` (a `MAP_WRITE` buffer no submission in flight
/// uses), unmapped again after.
fn write_mapped(gpu: &Gpu, upload: &wgpu::Buffer, bytes: &[u8]) -> Result<(), HarnessError> {
    let slice = upload.slice(..bytes.len() as u64);
    map(gpu, &slice, wgpu::MapMode::Write)?;
    slice
        .get_mapped_range_mut()
        .map_err(|e| HarnessError::Readback(format!("{e:?}")))?
        .copy_from_slice(bytes);
    upload.unmap();
    Ok(())
}

/// The first `bytes` of `staging` (a `MAP_READ` buffer the last submission copied into), as
/// words handed to `read` while mapped; unmapped again after.
fn read_back_with<R>(
    gpu: &Gpu,
    staging: &wgpu::Buffer,
    bytes: u64,
    read: impl FnOnce(&[u32]) -> R,
) -> Result<R, HarnessError> {
    let slice = staging.slice(..bytes);
    map(gpu, &slice, wgpu::MapMode::Read)?;
    let words = {
        let view = slice
            .get_mapped_range()
            .map_err(|e| HarnessError::Readback(format!("{e:?}")))?;
        read(bytemuck::cast_slice::<u8, u32>(&view))
    };
    staging.unmap();
    Ok(words)
}
