//! The compiling side: runs in a child process whose environment selects one driver and one
//! target (see [`super::target`]), compiles SPIR-V compute pipelines with the pipeline
//! statistics captured, and writes what the driver reports.
//!
//! The child is the program that asked (`std::env::current_exe`), entered through a
//! constructor that runs before `main` when [`CHILD_VAR`] is set: a test binary, errplot or a
//! user's program costs WGSL without a helper executable to install. The driver's shims make
//! submissions no-ops and read-backs garbage, so nothing here is ever run on a device: only
//! pipelines are created.
//!
//! The job and answer are plain text files (one record a line, tab-separated), so the protocol
//! needs no serialisation crate:
//! - job: `module<TAB>spv path<TAB>entry<TAB>bindings<TAB>disassembly(0|1)`, where bindings is
//!   one letter per binding of group 0 (`u` uniform, `r` read-only storage, `w` storage);
//! - answer: `driver<TAB>name<TAB>info`, then per module `module<TAB>index`, its executables'
//!   `executable<TAB>name<TAB>subgroup size` followed by `stat<TAB>name<TAB>value` lines and,
//!   when asked, `asm<TAB>line` lines; `error<TAB>message` for a module that failed.

use ash::vk;
use std::ffi::CStr;
use std::fmt::Write as _;

/// Set in the child's environment: the path of the job file (the answer goes to the same path
/// with `.out` appended).
pub const CHILD_VAR: &str = "PREPASS_ISA_CHILD_JOB";

// Runs before main in every program linking this module; does nothing unless the parent set
// CHILD_VAR, in which case it serves the job and exits without running main.
#[ctor::ctor(unsafe)]
fn serve_if_child() {
    let Some(job) = std::env::var_os(CHILD_VAR) else {
        return;
    };
    let job = std::path::PathBuf::from(job);
    let answer = match std::fs::read_to_string(&job) {
        Ok(text) => serve(&text),
        Err(e) => format!("fatal\tcannot read the job {}: {e}\n", job.display()),
    };
    let mut out = job.into_os_string();
    out.push(".out");
    let code = i32::from(std::fs::write(&out, answer).is_err());
    std::process::exit(code);
}

struct Job {
    spv: String,
    entry: String,
    bindings: Vec<vk::DescriptorType>,
    disassembly: bool,
}

fn parse(text: &str) -> Result<Vec<Job>, String> {
    text.lines()
        .filter(|l| !l.is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            if f.len() != 5 || f[0] != "module" {
                return Err(format!("bad job line {l:?}"));
            }
            let bindings = f[3]
                .chars()
                .map(|c| match c {
                    'u' => Ok(vk::DescriptorType::UNIFORM_BUFFER),
                    'r' | 'w' => Ok(vk::DescriptorType::STORAGE_BUFFER),
                    _ => Err(format!("bad binding letter {c:?}")),
                })
                .collect::<Result<_, _>>()?;
            Ok(Job {
                spv: f[1].to_string(),
                entry: f[2].to_string(),
                bindings,
                disassembly: f[4] == "1",
            })
        })
        .collect()
}

fn serve(text: &str) -> String {
    let jobs = match parse(text) {
        Ok(j) => j,
        Err(e) => return format!("fatal\t{e}\n"),
    };
    // SAFETY: the Vulkan calls below follow the specification's valid usage: every handle is
    // created before use and destroyed after its last use, on this one thread.
    match unsafe { Driver::open() } {
        Ok(driver) => {
            let mut out = format!("driver\t{}\t{}\n", driver.name, driver.info);
            for (k, job) in jobs.iter().enumerate() {
                let _ = writeln!(out, "module\t{k}");
                match unsafe { driver.compile(job) } {
                    Ok(text) => out.push_str(&text),
                    Err(e) => {
                        let _ = writeln!(out, "error\t{}", one_line(&e));
                    }
                }
            }
            unsafe { driver.close() };
            out
        }
        Err(e) => format!("fatal\t{}\n", one_line(&e)),
    }
}

fn one_line(s: &str) -> String {
    s.replace(['\t', '\n'], " ")
}

struct Driver {
    _entry: ash::Entry,
    instance: ash::Instance,
    device: ash::Device,
    exec: ash::khr::pipeline_executable_properties::Device,
    name: String,
    info: String,
}

fn text(raw: &[std::ffi::c_char]) -> String {
    // SAFETY: Vulkan's fixed-size string fields are NUL-terminated within their arrays.
    unsafe { CStr::from_ptr(raw.as_ptr()) }
        .to_string_lossy()
        .into_owned()
}

impl Driver {
    unsafe fn open() -> Result<Self, String> {
        let entry = unsafe { ash::Entry::load() }.map_err(|e| format!("no Vulkan loader: {e}"))?;
        let app = vk::ApplicationInfo::default().api_version(vk::API_VERSION_1_2);
        let instance = unsafe {
            entry.create_instance(
                &vk::InstanceCreateInfo::default().application_info(&app),
                None,
            )
        }
        .map_err(|e| format!("vkCreateInstance: {e}"))?;
        let physical = unsafe { instance.enumerate_physical_devices() }
            .map_err(|e| format!("vkEnumeratePhysicalDevices: {e}"))?;
        let Some(&physical) = physical.first() else {
            return Err("the driver exposes no device".into());
        };
        let mut driver_props = vk::PhysicalDeviceDriverProperties::default();
        let mut props = vk::PhysicalDeviceProperties2::default().push_next(&mut driver_props);
        unsafe { instance.get_physical_device_properties2(physical, &mut props) };
        let name = format!(
            "{} ({})",
            text(&props.properties.device_name),
            text(&driver_props.driver_name)
        );
        let info = text(&driver_props.driver_info);
        let families = unsafe { instance.get_physical_device_queue_family_properties(physical) };
        let family = families
            .iter()
            .position(|f| f.queue_flags.contains(vk::QueueFlags::COMPUTE))
            .ok_or("no compute queue")? as u32;
        let priorities = [1.0f32];
        let queues = [vk::DeviceQueueCreateInfo::default()
            .queue_family_index(family)
            .queue_priorities(&priorities)];
        let extensions = [ash::khr::pipeline_executable_properties::NAME.as_ptr()];
        let mut exec_features =
            vk::PhysicalDevicePipelineExecutablePropertiesFeaturesKHR::default()
                .pipeline_executable_info(true);
        let create = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_extension_names(&extensions)
            .push_next(&mut exec_features);
        let device = unsafe { instance.create_device(physical, &create, None) }
            .map_err(|e| format!("vkCreateDevice on {name}: {e}"))?;
        let exec = ash::khr::pipeline_executable_properties::Device::new(&instance, &device);
        Ok(Driver {
            _entry: entry,
            instance,
            device,
            exec,
            name,
            info,
        })
    }

    unsafe fn compile(&self, job: &Job) -> Result<String, String> {
        let bytes = std::fs::read(&job.spv).map_err(|e| format!("{}: {e}", job.spv))?;
        let words: Vec<u32> = bytes
            .chunks_exact(4)
            .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
            .collect();
        let d = &self.device;
        let module = unsafe {
            d.create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&words), None)
        }
        .map_err(|e| format!("vkCreateShaderModule: {e}"))?;
        let bindings: Vec<vk::DescriptorSetLayoutBinding> = job
            .bindings
            .iter()
            .enumerate()
            .map(|(k, &ty)| {
                vk::DescriptorSetLayoutBinding::default()
                    .binding(k as u32)
                    .descriptor_type(ty)
                    .descriptor_count(1)
                    .stage_flags(vk::ShaderStageFlags::COMPUTE)
            })
            .collect();
        let set_layout = unsafe {
            d.create_descriptor_set_layout(
                &vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings),
                None,
            )
        }
        .map_err(|e| format!("vkCreateDescriptorSetLayout: {e}"))?;
        let layouts = [set_layout];
        let layout = unsafe {
            d.create_pipeline_layout(
                &vk::PipelineLayoutCreateInfo::default().set_layouts(&layouts),
                None,
            )
        }
        .map_err(|e| format!("vkCreatePipelineLayout: {e}"))?;
        let entry = std::ffi::CString::new(job.entry.as_str()).map_err(|e| e.to_string())?;
        let mut flags = vk::PipelineCreateFlags::CAPTURE_STATISTICS_KHR;
        if job.disassembly {
            flags |= vk::PipelineCreateFlags::CAPTURE_INTERNAL_REPRESENTATIONS_KHR;
        }
        let info = vk::ComputePipelineCreateInfo::default()
            .flags(flags)
            .stage(
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(vk::ShaderStageFlags::COMPUTE)
                    .module(module)
                    .name(&entry),
            )
            .layout(layout);
        let result =
            unsafe { d.create_compute_pipelines(vk::PipelineCache::null(), &[info], None) };
        let answer = match result {
            Ok(p) => {
                let pipeline = p[0];
                let a = unsafe { self.read(pipeline, job.disassembly) };
                unsafe { d.destroy_pipeline(pipeline, None) };
                a
            }
            Err((_, e)) => Err(format!("vkCreateComputePipelines: {e}")),
        };
        unsafe {
            d.destroy_pipeline_layout(layout, None);
            d.destroy_descriptor_set_layout(set_layout, None);
            d.destroy_shader_module(module, None);
        }
        answer
    }

    unsafe fn read(&self, pipeline: vk::Pipeline, disassembly: bool) -> Result<String, String> {
        let mut out = String::new();
        let executables = unsafe {
            self.exec.get_pipeline_executable_properties(
                &vk::PipelineInfoKHR::default().pipeline(pipeline),
            )
        }
        .map_err(|e| format!("vkGetPipelineExecutablePropertiesKHR: {e}"))?;
        for (k, e) in executables.iter().enumerate() {
            let _ = writeln!(
                out,
                "executable\t{}\t{}",
                one_line(&text(&e.name)),
                e.subgroup_size
            );
            let which = vk::PipelineExecutableInfoKHR::default()
                .pipeline(pipeline)
                .executable_index(k as u32);
            let stats = unsafe { self.exec.get_pipeline_executable_statistics(&which) }
                .map_err(|e| format!("vkGetPipelineExecutableStatisticsKHR: {e}"))?;
            for s in &stats {
                // SAFETY: `format` names the union member the driver wrote.
                let value = unsafe {
                    match s.format {
                        vk::PipelineExecutableStatisticFormatKHR::BOOL32 => s.value.b32 as f64,
                        vk::PipelineExecutableStatisticFormatKHR::INT64 => s.value.i64 as f64,
                        vk::PipelineExecutableStatisticFormatKHR::UINT64 => s.value.u64 as f64,
                        vk::PipelineExecutableStatisticFormatKHR::FLOAT64 => s.value.f64,
                        _ => continue,
                    }
                };
                let _ = writeln!(out, "stat\t{}\t{value}", one_line(&text(&s.name)));
            }
            if disassembly {
                unsafe { self.disassembly(&which, &mut out) };
            }
        }
        Ok(out)
    }

    unsafe fn disassembly(&self, which: &vk::PipelineExecutableInfoKHR, out: &mut String) {
        // Two calls: sizes first, then the text into buffers of those sizes.
        let Ok(mut reps) = (unsafe {
            self.exec
                .get_pipeline_executable_internal_representations(which)
        }) else {
            return;
        };
        let mut buffers: Vec<Vec<u8>> = reps.iter().map(|r| vec![0u8; r.data_size]).collect();
        for (r, b) in reps.iter_mut().zip(&mut buffers) {
            r.p_data = b.as_mut_ptr().cast();
        }
        let mut count = reps.len() as u32;
        let fp = self
            .exec
            .fp()
            .get_pipeline_executable_internal_representations_khr;
        // SAFETY: `reps` holds `count` structures whose data pointers own `data_size` bytes.
        let ok = unsafe { fp(self.device.handle(), which, &mut count, reps.as_mut_ptr()) };
        if ok != vk::Result::SUCCESS && ok != vk::Result::INCOMPLETE {
            return;
        }
        for (r, b) in reps.iter().zip(&buffers) {
            let _ = writeln!(out, "asm\t== {}", one_line(&text(&r.name)));
            let body = String::from_utf8_lossy(b);
            for line in body.trim_end_matches('\0').lines() {
                let _ = writeln!(out, "asm\t{}", line.replace('\t', "    "));
            }
        }
    }

    unsafe fn close(self) {
        unsafe {
            self.device.destroy_device(None);
            self.instance.destroy_instance(None);
        }
    }
}
