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
//!
//! Files: `gpu.rs` (adapter, device, caches), `arg.rs` and `output.rs` (what goes in and comes
//! out), `kernel.rs` (compiling and running a function), `dispatch.rs` (a dispatch for another
//! implementation), `buffers.rs` (bind group and mapping), `codegen.rs` (the generated entry
//! point), `signature.rs` (reading the function's signature), `timing.rs` (GPU timing); this
//! file holds the error type.

mod arg;
mod buffers;
mod codegen;
mod dispatch;
mod gpu;
mod kernel;
mod output;
mod signature;
mod timing;

pub use arg::Arg;
pub use codegen::{Feed, TimedBody, WORKGROUP_SIZE};
pub use dispatch::Dispatch;
pub use gpu::Gpu;
pub use kernel::{Kernel, MAX_CHUNK};
pub use output::Output;
pub use signature::{Param, Scalar, Signature, SignatureError, ValueType};
pub use timing::{DEFAULT_TIMING_TILE, MIN_TIMED_INVOCATIONS, Timing, TimingMethod};

// One namespace for the parts (each does `use super::*`), as when they were one file.
use buffers::*;

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
    /// The adapter's `+ − ×` cannot carry the conforming emulation
    /// ([`crate::conforming::check_host`]): the message names the helper, the input and the
    /// suspected freedom (contraction, reassociation or flushing).
    UnfitHost(String),
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
            Self::UnfitHost(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for HarnessError {}

impl From<SignatureError> for HarnessError {
    fn from(e: SignatureError) -> Self {
        Self::Signature(e)
    }
}
