//! The instruction sets costed, and the driver environment that selects each one.

use std::path::{Path, PathBuf};

/// The GPU vendor whose compiler reads a target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Vendor {
    /// Mesa's RADV driver, ACO compiler; figures per wave64.
    Amd,
    /// Mesa's ANV driver, brw compiler; figures per SIMD thread.
    Intel,
}

/// One instruction set, compiled by Mesa's own compiler for it without the hardware.
///
/// AMD targets go through RADV with Mesa's amdgpu noop kernel-driver shim
/// (`libamdgpu_noop_drm_shim.so`, `AMDGPU_GPU_ID`), Intel targets through ANV with Mesa's
/// Intel noop shim (`libintel_noop_drm_shim.so`, `INTEL_STUB_GPU_PLATFORM`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Target {
    /// AMD GCN4, Radeon RX 480/580 (`polaris10`).
    Gcn4,
    /// AMD GCN5, Radeon RX Vega 56/64 (`vega10`).
    Gcn5,
    /// AMD RDNA2, Radeon RX 6800/6900 (`navi21`); also the consoles' generation.
    Rdna2,
    /// AMD RDNA3, Radeon RX 7900 (`navi31`).
    Rdna3,
    /// Intel Gen9, Skylake integrated graphics (`skl`).
    Gen9,
    /// Intel Gen12, Tiger Lake Xe-LP integrated graphics (`tgl`).
    Gen12,
    /// Intel Xe-HPG, Arc A-series (`dg2`).
    XeHpg,
    /// Intel Xe2, Lunar Lake integrated graphics (`lnl`).
    Xe2,
}

impl Target {
    /// Every target, AMD oldest first, then Intel oldest first.
    pub const ALL: [Target; 8] = [
        Target::Gcn4,
        Target::Gcn5,
        Target::Rdna2,
        Target::Rdna3,
        Target::Gen9,
        Target::Gen12,
        Target::XeHpg,
        Target::Xe2,
    ];

    /// Whose compiler reads it.
    pub fn vendor(self) -> Vendor {
        match self {
            Target::Gcn4 | Target::Gcn5 | Target::Rdna2 | Target::Rdna3 => Vendor::Amd,
            _ => Vendor::Intel,
        }
    }

    /// The chip name the shim is given (`AMDGPU_GPU_ID` or `INTEL_STUB_GPU_PLATFORM`).
    pub fn chip(self) -> &'static str {
        match self {
            Target::Gcn4 => "polaris10",
            Target::Gcn5 => "vega10",
            Target::Rdna2 => "navi21",
            Target::Rdna3 => "navi31",
            Target::Gen9 => "skl",
            Target::Gen12 => "tgl",
            Target::XeHpg => "dg2",
            Target::Xe2 => "lnl",
        }
    }

    /// The architecture's name: `RDNA2`, `Xe-HPG`, …
    pub fn arch(self) -> &'static str {
        match self {
            Target::Gcn4 => "GCN4",
            Target::Gcn5 => "GCN5",
            Target::Rdna2 => "RDNA2",
            Target::Rdna3 => "RDNA3",
            Target::Gen9 => "Gen9",
            Target::Gen12 => "Gen12",
            Target::XeHpg => "Xe-HPG",
            Target::Xe2 => "Xe2",
        }
    }

    /// `RDNA2 (navi21)`: the architecture and the chip it was compiled for.
    pub fn label(self) -> String {
        format!("{} ({})", self.arch(), self.chip())
    }

    /// Looks a target up by its chip or architecture name, any case (`navi21`, `rdna2`).
    pub fn from_name(name: &str) -> Option<Target> {
        let n = name.to_ascii_lowercase();
        Target::ALL
            .into_iter()
            .find(|t| t.chip() == n || t.arch().to_ascii_lowercase() == n)
    }
}

impl std::fmt::Display for Target {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.label())
    }
}

/// The variable naming the folder `.ci/setup-gpu-compilers` fills: Mesa's unpacked
/// `usr/lib/x86_64-linux-gnu` (RADV, ANV, the amdgpu shim, libdrm) and
/// `intel/libintel_noop_drm_shim.so`.
pub const ROOT_VAR: &str = "PREPASS_GPU_COMPILERS";

/// Where the compilers are: `$PREPASS_GPU_COMPILERS`, else the setup script's default folder
/// (`$HOME/.cache/prepass/gpu-compilers-25.0.7`).
pub fn default_root() -> Option<PathBuf> {
    if let Some(r) = std::env::var_os(ROOT_VAR) {
        return Some(PathBuf::from(r));
    }
    std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache/prepass/gpu-compilers-25.0.7"))
}

/// The driver environment for one target: variables to set in the child, or why the target
/// cannot be compiled for here.
pub(crate) fn environment(root: &Path, target: Target) -> Result<Vec<(String, String)>, String> {
    let lib = root.join("usr/lib/x86_64-linux-gnu");
    let (driver, shim, chip_var) = match target.vendor() {
        Vendor::Amd => (
            lib.join("libvulkan_radeon.so"),
            lib.join("libamdgpu_noop_drm_shim.so"),
            "AMDGPU_GPU_ID",
        ),
        Vendor::Intel => (
            lib.join("libvulkan_intel.so"),
            root.join("intel/libintel_noop_drm_shim.so"),
            "INTEL_STUB_GPU_PLATFORM",
        ),
    };
    for needed in [&driver, &shim] {
        if !needed.is_file() {
            return Err(format!(
                "{} is missing (run `bash .ci/setup-gpu-compilers`, or set {ROOT_VAR} to the \
                 folder it fills)",
                needed.display()
            ));
        }
    }
    // The loader reads this ICD manifest only; it is written beside the driver once.
    let manifest = root.join(format!(
        "{}_icd.prepass.json",
        match target.vendor() {
            Vendor::Amd => "radeon",
            Vendor::Intel => "intel",
        }
    ));
    if !manifest.is_file() {
        let json = format!(
            "{{\"file_format_version\":\"1.0.1\",\"ICD\":{{\"library_path\":\"{}\",\"api_version\":\"1.4.305\"}}}}\n",
            driver.display()
        );
        std::fs::write(&manifest, json)
            .map_err(|e| format!("cannot write {}: {e}", manifest.display()))?;
    }
    let path = |p: &Path| p.to_string_lossy().into_owned();
    let mut ld_path = path(&lib);
    if let Some(old) = std::env::var_os("LD_LIBRARY_PATH") {
        ld_path = format!("{ld_path}:{}", old.to_string_lossy());
    }
    Ok(vec![
        ("VK_DRIVER_FILES".into(), path(&manifest)),
        ("VK_ICD_FILENAMES".into(), path(&manifest)),
        ("LD_LIBRARY_PATH".into(), ld_path),
        ("LD_PRELOAD".into(), path(&shim)),
        (chip_var.into(), target.chip().into()),
        // Compile every time (a cache hit reports no fresh statistics), and let no layer pick
        // another device.
        ("MESA_SHADER_CACHE_DISABLE".into(), "true".into()),
        ("MESA_SHADER_CACHE_MAX_SIZE".into(), "0".into()),
        ("NODEVICE_SELECT".into(), "1".into()),
        ("VK_LOADER_LAYERS_DISABLE".into(), "~all~".into()),
        ("VK_INSTANCE_LAYERS".into(), String::new()),
    ])
}
