//! [`Gpu`]: the adapter and device a harness runs on, its pipeline cache and buffer pool,
//! and [`Gpu::run_dispatch`] for a [`Dispatch`] made elsewhere.

use super::*;

/// An adapter and a device on it.
pub struct Gpu {
    pub(super) adapter: wgpu::Adapter,
    pub(super) device: wgpu::Device,
    pub(super) queue: wgpu::Queue,
    /// Every pipeline built on this device, by its full WGSL: a kernel another test (or another
    /// policy served by the same module) already compiled is not compiled again. On a CPU
    /// adapter compilation costs far more than running.
    pub(super) pipelines: Mutex<std::collections::HashMap<String, wgpu::ComputePipeline>>,
    /// Buffers of finished runs, oldest first, for the next run that needs one of the same
    /// usage and size ([`Gpu::take_buffer`]).
    pub(super) buffers: Mutex<Vec<wgpu::Buffer>>,
}

/// At most this many bytes of buffers wait in [`Gpu`]'s pool for reuse (oldest given up
/// first): a sweep of 2^24 elements runs in chunks of [`MAX_CHUNK`], each chunk's column,
/// output and readback buffers up to 64 MiB.
pub(super) const POOL_BYTES: u64 = 512 << 20;

pub(super) fn device_rank(t: wgpu::DeviceType) -> u8 {
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
    pub(super) fn take_buffer(
        &self,
        size: u64,
        usage: wgpu::BufferUsages,
        label: &str,
    ) -> wgpu::Buffer {
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
    pub(super) fn give_back(&self, buffers: impl IntoIterator<Item = wgpu::Buffer>) {
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
