//! GPU time per evaluation of a WGSL function, over one dispatch of at least 2^24 invocations.
//!
//! Two kernels run the same dispatch: the function, and an empty-kernel baseline that loads the
//! same arguments and stores the same bytes without calling it
//! ([`TimedBody::Baseline`](super::TimedBody::Baseline)). The time per evaluation is the
//! difference divided by the invocation count, so dispatch overhead, loads and stores cancel and
//! what is left is the function's own arithmetic. Each kernel runs `repeats` times; the fastest
//! run of each counts (the least disturbed by other work on the machine).
//!
//! The clock is the adapter's timestamp queries around the compute pass where the device has
//! `TIMESTAMP_QUERY` ([`Gpu::new`] requests it when the adapter offers it), otherwise the wall
//! time from submission to completion on the CPU. [`Timing::method`] says which.
//!
//! On a software adapter ([`Gpu::is_software`], e.g. lavapipe) the numbers are CPU time of the
//! driver's JIT-compiled shader: they rank functions on that CPU and say nothing about a GPU.

use super::codegen::{self, TimedBody};
use super::{Arg, HarnessError, Kernel, WORKGROUP_SIZE, read_back};
use std::time::Instant;

/// The smallest dispatch [`Kernel::time`] accepts: 2^24 invocations.
pub const MIN_TIMED_INVOCATIONS: u64 = 1 << 24;

/// Output slots of a timed dispatch when no column fixes the tile (see [`Kernel::time`]).
pub const DEFAULT_TIMING_TILE: u64 = 1 << 16;

/// Which clock measured a [`Timing`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TimingMethod {
    /// The adapter's timestamp queries at the start and end of the compute pass.
    TimestampQuery,
    /// Wall time on the CPU from `submit` until the device reports the work done.
    WallClock,
}

impl std::fmt::Display for TimingMethod {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::TimestampQuery => "timestamp queries",
            Self::WallClock => "submission wall time",
        })
    }
}

/// GPU time of one function over one dispatch, and of the empty-kernel baseline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// The clock used.
    pub method: TimingMethod,
    /// Invocations per dispatch (each evaluates the function once).
    pub invocations: u64,
    /// Dispatches timed per kernel; the fastest counts.
    pub repeats: u32,
    /// Fastest dispatch of the function kernel, nanoseconds.
    pub function_ns: f64,
    /// Fastest dispatch of the baseline kernel, nanoseconds.
    pub baseline_ns: f64,
}

impl Timing {
    /// `(function − baseline) / invocations`: nanoseconds the function adds per evaluation.
    /// Can come out slightly negative for a function cheaper than the noise between runs; it is
    /// reported as measured, not clamped.
    pub fn ns_per_eval(&self) -> f64 {
        (self.function_ns - self.baseline_ns) / self.invocations as f64
    }

    /// `function / invocations`: nanoseconds per evaluation including loads and stores.
    pub fn gross_ns_per_eval(&self) -> f64 {
        self.function_ns / self.invocations as f64
    }
}

impl Kernel<'_> {
    /// Time the function over one dispatch of `n ≥ 2^24` invocations (see the module docs),
    /// with timestamp queries when the device has them, otherwise wall time.
    ///
    /// Arguments are fed as in [`Kernel::run`], except that columns are tiles: every column
    /// must hold the same power-of-two number of values `m ≤ n`, and invocation `i` reads
    /// element `i mod m` (and stores to slot `i mod m`). With no columns the tile is
    /// [`DEFAULT_TIMING_TILE`]. `Arg::Index` still feeds `start + i`.
    pub fn time(&self, args: &[Arg<'_>], n: u64, repeats: u32) -> Result<Timing, HarnessError> {
        let has_timestamps = self
            .gpu
            .device
            .features()
            .contains(wgpu::Features::TIMESTAMP_QUERY);
        let method = if has_timestamps {
            TimingMethod::TimestampQuery
        } else {
            TimingMethod::WallClock
        };
        self.time_with(args, n, repeats, method)
    }

    /// [`Kernel::time`] with the clock chosen by the caller; asking for timestamp queries on a
    /// device without them is an error.
    pub fn time_with(
        &self,
        args: &[Arg<'_>],
        n: u64,
        repeats: u32,
        method: TimingMethod,
    ) -> Result<Timing, HarnessError> {
        let sig = &self.signature;
        if n < MIN_TIMED_INVOCATIONS {
            return Err(HarnessError::Arguments(format!(
                "a timed dispatch needs at least 2^24 invocations, {n} asked"
            )));
        }
        if repeats == 0 {
            return Err(HarnessError::Arguments("repeats must be at least 1".into()));
        }
        self.check_arity(args)?;
        let gpu = self.gpu;
        if method == TimingMethod::TimestampQuery
            && !gpu
                .device
                .features()
                .contains(wgpu::Features::TIMESTAMP_QUERY)
        {
            return Err(HarnessError::Device(
                "the device has no TIMESTAMP_QUERY; time with TimingMethod::WallClock".into(),
            ));
        }
        let mut tile = None;
        for (p, a) in sig.params.iter().zip(args) {
            match a {
                Arg::Column(bytes) => {
                    let stride = p.ty.words() * 4;
                    let m = (bytes.len() / stride) as u64;
                    if bytes.len() % stride != 0 || !m.is_power_of_two() || m > n {
                        return Err(HarnessError::Arguments(format!(
                            "timing column for `{}: {}` must hold a power-of-two number of \
                             values ≤ {n}; it holds {} bytes",
                            p.name,
                            p.ty,
                            bytes.len()
                        )));
                    }
                    if tile.is_some_and(|t| t != m) {
                        return Err(HarnessError::Arguments(
                            "timing columns must all hold the same number of values".into(),
                        ));
                    }
                    tile = Some(m);
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
        let tile = tile.unwrap_or(DEFAULT_TIMING_TILE.min(n));
        let limits = gpu.device.limits();
        let per_dim = u64::from(limits.max_compute_workgroups_per_dimension);
        let wg = u64::from(WORKGROUP_SIZE);
        let groups = n.div_ceil(wg);
        let gx = groups.min(per_dim);
        let gy = groups.div_ceil(gx);
        if gy > per_dim || gx * wg > u64::from(u32::MAX) || n > u64::from(u32::MAX) {
            return Err(HarnessError::Arguments(format!(
                "{n} invocations do not fit one dispatch"
            )));
        }

        let feeds: Vec<_> = args.iter().map(Arg::feed).collect();
        let device = &gpu.device;
        let mk = |size: u64, usage: wgpu::BufferUsages| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("prepass timing"),
                size: size.max(4),
                usage,
                mapped_at_creation: false,
            })
        };
        let mut uniform = vec![n as u32, (gx * wg) as u32, (tile - 1) as u32, 0];
        for a in args {
            uniform.extend_from_slice(&match *a {
                Arg::Splat(v) => v,
                Arg::Index { start } => [start, 0, 0, 0],
                Arg::Column(_) => [0; 4],
            });
        }
        if args.is_empty() {
            uniform.extend_from_slice(&[0; 4]);
        }
        let params = mk(
            uniform.len() as u64 * 4,
            wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        );
        gpu.queue
            .write_buffer(&params, 0, bytemuck::cast_slice(&uniform));
        let mut columns = Vec::new();
        for a in args {
            if let Arg::Column(bytes) = a {
                let b = mk(
                    bytes.len() as u64,
                    wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
                );
                gpu.queue.write_buffer(&b, 0, bytes);
                columns.push(b);
            }
        }
        let out = mk(
            tile * sig.result.words() as u64 * 4,
            wgpu::BufferUsages::STORAGE,
        );
        let queries = (method == TimingMethod::TimestampQuery).then(|| {
            let set = device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("prepass timing"),
                ty: wgpu::QueryType::Timestamp,
                count: 2,
            });
            let resolve = mk(
                16,
                wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            );
            let staging = mk(
                16,
                wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            );
            (set, resolve, staging)
        });

        let mut kernels = Vec::new();
        for body in [TimedBody::Function, TimedBody::Baseline] {
            let label = format!("{} timing {body:?}", sig.function);
            let source = format!(
                "{}\n\n// ---- generated by prepass::harness (timing) ----\n{}",
                self.source,
                codegen::timing_entry_point(sig, &feeds, body)
            );
            let pipeline = self.compile(&source, &label)?;
            let bind_group =
                super::bind_group(device, &pipeline, &params, columns.iter(), &out, &label);
            kernels.push((pipeline, bind_group));
        }
        // Round 0 is an untimed warm-up (first-use costs: shader JIT, page faults) of a
        // sixteenth of the dispatch: every invocation reads and writes the same tile-sized
        // buffers (`i & (tile − 1)`), so that many touch all of them, and a full-size warm-up
        // was a third of a quick report's timing (repeats = 1). The two kernels alternate
        // within each round, so a change in machine load between rounds touches both alike.
        let warm_groups = (n / 16).max(tile).div_ceil(wg);
        let warm_x = warm_groups.min(gx);
        let warm = (warm_x, warm_groups.div_ceil(warm_x));
        let mut best = [f64::INFINITY; 2];
        for round in 0..=repeats {
            let (dx, dy) = if round == 0 { warm } else { (gx, gy) };
            for (slot, (pipeline, bind_group)) in kernels.iter().enumerate() {
                let mut encoder =
                    device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
                {
                    let timestamp_writes =
                        queries
                            .as_ref()
                            .map(|(set, _, _)| wgpu::ComputePassTimestampWrites {
                                query_set: set,
                                beginning_of_pass_write_index: Some(0),
                                end_of_pass_write_index: Some(1),
                            });
                    let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                        label: None,
                        timestamp_writes,
                    });
                    pass.set_pipeline(pipeline);
                    pass.set_bind_group(0, bind_group, &[]);
                    pass.dispatch_workgroups(dx as u32, dy as u32, 1);
                }
                if let Some((set, resolve, staging)) = &queries {
                    encoder.resolve_query_set(set, 0..2, resolve, 0);
                    encoder.copy_buffer_to_buffer(resolve, 0, staging, 0, 16);
                }
                let started = Instant::now();
                gpu.queue.submit([encoder.finish()]);
                device
                    .poll(wgpu::PollType::wait_indefinitely())
                    .map_err(|e| HarnessError::Readback(e.to_string()))?;
                let wall_ns = started.elapsed().as_secs_f64() * 1e9;
                let ns = match &queries {
                    Some((_, _, staging)) => {
                        let w = read_back(gpu, staging, 16)?;
                        let begin = u64::from(w[0]) | (u64::from(w[1]) << 32);
                        let end = u64::from(w[2]) | (u64::from(w[3]) << 32);
                        end.wrapping_sub(begin) as f64 * f64::from(gpu.queue.get_timestamp_period())
                    }
                    None => wall_ns,
                };
                if round > 0 {
                    best[slot] = best[slot].min(ns);
                }
            }
        }
        Ok(Timing {
            method,
            invocations: n,
            repeats,
            function_ns: best[0],
            baseline_ns: best[1],
        })
    }
}
