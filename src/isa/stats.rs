//! The drivers' statistics, read from the child's answer, and the net figures made from them.

use super::target::{Target, Vendor};

/// One compiled kernel's statistics as the driver reported them (the figures a target lacks are
/// `None`: ACO has no cycle estimate, brw no latency model).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Stats {
    /// The executable's name (`Compute Shader`, `SIMD16 Compute Shader`, …).
    pub executable: String,
    /// Its subgroup size: 64 on AMD (wave64), the SIMD width on Intel.
    pub subgroup_size: u32,
    /// Instructions: ACO's `Instructions`, brw's `Instruction Count`.
    pub instructions: f64,
    /// ALU instructions: ACO's `VALU` + `SALU`; brw's instructions less its `SEND Count`
    /// (SENDs are its memory and message instructions).
    pub alu: f64,
    /// ACO's `Latency`: cycles along the critical path of its scheduling model (memory 320
    /// cycles, loops 8 iterations, branches taken half the time).
    pub latency: Option<f64>,
    /// ACO's `Inverse Throughput`: cycles per wave when the SIMD is kept busy.
    pub inverse_throughput: Option<f64>,
    /// brw's `Cycle Count`: its static estimate of the thread's cycles.
    pub cycles: Option<f64>,
    /// Vector registers: ACO's `VGPRs`; brw's `Max live registers` (GRF-sized).
    pub registers: f64,
    /// ACO's `SGPRs` (scalar registers); none on Intel.
    pub scalar_registers: Option<f64>,
    /// Spilled registers: ACO's spilled SGPRs + VGPRs; brw's spill + fill counts.
    pub spills: f64,
    /// ACO's `Subgroups per SIMD` (waves resident at once); none on Intel.
    pub occupancy: Option<f64>,
    /// Every statistic as the driver named it.
    pub raw: Vec<(String, f64)>,
}

impl Stats {
    fn from_raw(
        vendor: Vendor,
        executable: String,
        subgroup_size: u32,
        raw: Vec<(String, f64)>,
    ) -> Self {
        let get = |name: &str| raw.iter().find(|(n, _)| n == name).map(|&(_, v)| v);
        let sum = |names: &[&str]| names.iter().filter_map(|n| get(n)).sum::<f64>();
        match vendor {
            Vendor::Amd => Stats {
                executable,
                subgroup_size,
                instructions: get("Instructions").unwrap_or(f64::NAN),
                alu: if get("VALU").is_some() {
                    sum(&["VALU", "SALU"])
                } else {
                    f64::NAN
                },
                latency: get("Latency"),
                inverse_throughput: get("Inverse Throughput"),
                cycles: None,
                registers: get("VGPRs").unwrap_or(f64::NAN),
                scalar_registers: get("SGPRs"),
                spills: sum(&["Spilled SGPRs", "Spilled VGPRs"]),
                occupancy: get("Subgroups per SIMD"),
                raw,
            },
            Vendor::Intel => {
                let instructions = get("Instruction Count").unwrap_or(f64::NAN);
                Stats {
                    executable,
                    subgroup_size,
                    instructions,
                    alu: instructions - get("SEND Count").unwrap_or(f64::NAN),
                    latency: None,
                    inverse_throughput: None,
                    cycles: get("Cycle Count"),
                    registers: get("Max live registers").unwrap_or(f64::NAN),
                    scalar_registers: None,
                    spills: sum(&["Spill Count", "Fill Count"]),
                    occupancy: None,
                    raw,
                }
            }
        }
    }
}

/// Per-evaluation figures, net of the baseline (see the [module docs](super)).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Net {
    /// Instructions per evaluation: `(f_k − b_k) / k`.
    pub instructions: f64,
    /// ALU instructions per evaluation.
    pub alu: f64,
    /// ACO latency of one evaluation: `f_1 − b_1` (AMD only).
    pub latency: Option<f64>,
    /// ACO inverse throughput per evaluation (AMD only).
    pub inverse_throughput: Option<f64>,
    /// brw cycles per evaluation (Intel only).
    pub cycles: Option<f64>,
}

impl Net {
    /// The figure a target is ranked by: ACO's inverse throughput on AMD, brw's cycles on Intel.
    pub fn rank(&self) -> f64 {
        self.inverse_throughput
            .or(self.cycles)
            .unwrap_or(self.instructions)
    }
}

/// What one function costs on one target.
#[derive(Clone, Debug, PartialEq)]
pub struct Cost {
    /// Net per evaluation.
    pub net: Net,
    /// The function's `k = 1` kernel as compiled (registers, spills, occupancy).
    pub kernel: Stats,
    /// The `k = 1` baseline kernel as compiled.
    pub baseline: Stats,
    /// Evaluations per invocation of the k-way kernels.
    pub independent: u32,
    /// The `k = 1` kernel's disassembly, when [`Costing::disassembly`](super::Costing::disassembly)
    /// asked for it.
    pub disassembly: Option<String>,
}

impl Cost {
    pub(crate) fn net(k: u32, fk: &Compiled, bk: &Compiled, f1: &Compiled, b1: &Compiled) -> Self {
        let per = |f: f64, b: f64| (f - b) / f64::from(k);
        let opt = |f: Option<f64>, b: Option<f64>| Some(per(f?, b?));
        let (f, b) = (&fk.stats, &bk.stats);
        let net = Net {
            instructions: per(f.instructions, b.instructions),
            alu: per(f.alu, b.alu),
            latency: match (f1.stats.latency, b1.stats.latency) {
                (Some(x), Some(y)) => Some(x - y),
                _ => None,
            },
            inverse_throughput: opt(f.inverse_throughput, b.inverse_throughput),
            cycles: opt(f.cycles, b.cycles),
        };
        Cost {
            net,
            kernel: f1.stats.clone(),
            baseline: b1.stats.clone(),
            independent: k,
            disassembly: f1.disassembly.clone(),
        }
    }
}

/// One module of the child's answer.
#[derive(Clone, Debug)]
pub(crate) struct Compiled {
    pub stats: Stats,
    pub disassembly: Option<String>,
}

pub(crate) struct Answer {
    pub driver: String,
    pub driver_info: String,
    pub modules: Vec<Result<Compiled, String>>,
}

/// Reads the child's answer (format: `child.rs`). Of several executables (a driver may report
/// more than one SIMD width), the last is the one kept: ANV lists the variants it compiled
/// and dispatches the widest that fits, which it lists last.
pub(crate) fn parse_answer(text: &str, modules: usize, vendor: Vendor) -> Result<Answer, String> {
    let mut driver = None;
    let mut out: Vec<Result<Compiled, String>> = Vec::new();
    // An executable as read so far: its name, subgroup size and statistics.
    type Executable = (String, u32, Vec<(String, f64)>);
    struct Open {
        exe: Option<Executable>,
        asm: Vec<String>,
        err: Option<String>,
    }
    let mut cur: Option<Open> = None;
    let close = |o: Open, out: &mut Vec<Result<Compiled, String>>| {
        out.push(match (o.err, o.exe) {
            (Some(e), _) => Err(e),
            (None, Some((name, size, raw))) => Ok(Compiled {
                stats: Stats::from_raw(vendor, name, size, raw),
                disassembly: (!o.asm.is_empty()).then(|| o.asm.join("\n")),
            }),
            (None, None) => Err("the driver reported no executable".into()),
        });
    };
    for line in text.lines() {
        let f: Vec<&str> = line.splitn(3, '\t').collect();
        match f[0] {
            "fatal" => return Err(f.get(1).copied().unwrap_or("").to_string()),
            "driver" if f.len() == 3 => driver = Some((f[1].to_string(), f[2].to_string())),
            "module" => {
                if let Some(o) = cur.take() {
                    close(o, &mut out);
                }
                cur = Some(Open {
                    exe: None,
                    asm: Vec::new(),
                    err: None,
                });
            }
            "error" => {
                if let Some(o) = cur.as_mut() {
                    o.err = Some(f.get(1).copied().unwrap_or("").to_string());
                }
            }
            "executable" if f.len() == 3 => {
                if let Some(o) = cur.as_mut() {
                    o.exe = Some((f[1].to_string(), f[2].parse().unwrap_or(0), Vec::new()));
                    o.asm.clear();
                }
            }
            "stat" if f.len() == 3 => {
                if let Some((_, _, raw)) = cur.as_mut().and_then(|o| o.exe.as_mut()) {
                    raw.push((f[1].to_string(), f[2].parse().unwrap_or(f64::NAN)));
                }
            }
            "asm" => {
                if let Some(o) = cur.as_mut() {
                    o.asm.push(f.get(1).copied().unwrap_or("").to_string());
                }
            }
            _ => return Err(format!("unreadable answer line {line:?}")),
        }
    }
    if let Some(o) = cur.take() {
        close(o, &mut out);
    }
    let (driver, driver_info) = driver.ok_or("the child named no driver")?;
    if out.len() != modules {
        return Err(format!(
            "the child answered {} of {modules} modules",
            out.len()
        ));
    }
    Ok(Answer {
        driver,
        driver_info,
        modules: out,
    })
}

/// The chip the driver says it compiled for, when that is not `target`'s (a shim that did not
/// take would otherwise cost everything for whatever the driver found).
pub(crate) fn device_mismatch(target: Target, driver: &str) -> Option<String> {
    let d = driver.to_ascii_lowercase();
    let expect: &[&str] = match target {
        Target::Gcn4 => &["polaris10"],
        Target::Gcn5 => &["vega10"],
        Target::Rdna2 => &["navi21"],
        Target::Rdna3 => &["navi31"],
        Target::Gen9 => &["skl", "skylake", "hd graphics"],
        Target::Gen12 => &["tgl", "tiger lake", "xe graphics"],
        Target::XeHpg => &["dg2", "arc"],
        Target::Xe2 => &["lnl", "lunar lake", "xe2", "arc"],
    };
    (!expect.iter().any(|e| d.contains(e))).then(|| driver.to_string())
}
