//! Parse, validate and translate WGSL with naga, the compiler wgpu itself uses.

use naga::back::{glsl, hlsl, msl, spv};
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};
use naga::{Module, ShaderStage, TypeInner};
use std::fmt::Write as _;

/// A WGSL source that failed a naga stage, with naga's message (spans rendered against the
/// source, so the offending line is shown).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WgslError {
    /// Which stage failed: `parse`, `validate`, `spirv`, `msl`, `hlsl`, `glsl` or `call`.
    pub stage: &'static str,
    /// naga's rendered message.
    pub message: String,
}

impl std::fmt::Display for WgslError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "WGSL {} failed: {}", self.stage, self.message)
    }
}

impl std::error::Error for WgslError {}

fn err(stage: &'static str, message: impl ToString) -> WgslError {
    WgslError {
        stage,
        message: message.to_string(),
    }
}

/// A parsed and validated module.
#[derive(Debug)]
pub struct Checked {
    /// naga's IR of the source.
    pub module: Module,
    /// naga's validation results (needed by its backends).
    pub info: ModuleInfo,
}

/// Parse `source` and validate it with every validation flag and the capabilities WebGPU
/// guarantees (no native-only features), so what passes here runs on every wgpu backend.
pub fn parse_and_validate(source: &str) -> Result<Checked, WgslError> {
    let module =
        naga::front::wgsl::parse_str(source).map_err(|e| err("parse", e.emit_to_string(source)))?;
    // SHADER_FLOAT16_IN_FLOAT32 covers core WGSL's `pack2x16float`/`unpack2x16float`/
    // `quantizeToF16`: part of WebGPU's compliant set (wgpu's DownlevelFlags::SHADER_F16_IN_F32),
    // which wgpu withholds only on Mesa Vulkan drivers without shaderFloat16 (lavapipe has it).
    let info = Validator::new(
        ValidationFlags::all(),
        Capabilities::SHADER_FLOAT16_IN_FLOAT32,
    )
    .validate(&module)
    .map_err(|e| err("validate", e.emit_to_string(source)))?;
    Ok(Checked { module, info })
}

/// What naga's four backends produced for a source.
#[derive(Clone, Debug, Default)]
pub struct Translations {
    /// SPIR-V words (Vulkan).
    pub spirv: Vec<u32>,
    /// Metal Shading Language.
    pub msl: String,
    /// HLSL (Direct3D 12).
    pub hlsl: String,
    /// GLSL ES 3.10 compute shader.
    pub glsl: String,
}

/// Name of the compute entry point that [`translate_all`] appends to call every function.
pub const CALL_ALL_ENTRY: &str = "prepass_call_all";

/// Translate a library of WGSL functions through naga's SPIR-V, MSL, HLSL and GLSL backends.
///
/// Backends emit only what an entry point reaches (GLSL needs exactly one), so a compute entry
/// point [`CALL_ALL_ENTRY`] is appended that calls every function of the source with
/// zero-valued arguments: every function is then translated by every backend. A function whose
/// arguments cannot be zero-constructed (pointers, runtime arrays, handles) is an error.
pub fn translate_all(source: &str) -> Result<Translations, WgslError> {
    let base = parse_and_validate(source)?;
    let caller = call_all_entry_point(&base.module)?;
    let full = format!("{source}\n{caller}");
    let Checked { module, info } = parse_and_validate(&full)?;

    let spirv = spv::write_vec(&module, &info, &spv::Options::default(), None)
        .map_err(|e| err("spirv", e))?;
    let (msl, _) = msl::write_string(
        &module,
        &info,
        &msl::Options::default(),
        &msl::PipelineOptions::default(),
    )
    .map_err(|e| err("msl", e))?;
    let mut hlsl = String::new();
    let hlsl_options = hlsl::Options::default();
    hlsl::Writer::new(&mut hlsl, &hlsl_options, &hlsl::PipelineOptions::default())
        .write(&module, &info, None)
        .map_err(|e| err("hlsl", e))?;
    let mut glsl = String::new();
    let glsl_options = glsl::Options {
        version: glsl::Version::new_gles(310),
        ..Default::default()
    };
    let pipeline = glsl::PipelineOptions {
        shader_stage: ShaderStage::Compute,
        entry_point: CALL_ALL_ENTRY.to_string(),
        multiview: None,
    };
    glsl::Writer::new(
        &mut glsl,
        &module,
        &info,
        &glsl_options,
        &pipeline,
        naga::proc::BoundsCheckPolicies::default(),
    )
    .and_then(|mut w| w.write().map(|_| ()))
    .map_err(|e| err("glsl", e))?;
    Ok(Translations {
        spirv,
        msl,
        hlsl,
        glsl,
    })
}

fn call_all_entry_point(module: &Module) -> Result<String, WgslError> {
    let mut body = String::new();
    for (_, function) in module.functions.iter() {
        let Some(name) = &function.name else { continue };
        let mut args = Vec::new();
        for a in &function.arguments {
            args.push(format!("{}()", wgsl_type_name(module, a.ty, name)?));
        }
        let call = format!("{name}({})", args.join(", "));
        if function.result.is_some() {
            let _ = writeln!(body, "    _ = {call};");
        } else {
            let _ = writeln!(body, "    {call};");
        }
    }
    Ok(format!(
        "@compute @workgroup_size(1)\nfn {CALL_ALL_ENTRY}() {{\n{body}}}\n"
    ))
}

/// WGSL spelling of a constructible type, for a zero-value constructor `T()`.
fn wgsl_type_name(
    module: &Module,
    ty: naga::Handle<naga::Type>,
    function: &str,
) -> Result<String, WgslError> {
    let scalar = |s: naga::Scalar| -> Result<&'static str, WgslError> {
        use naga::ScalarKind::*;
        Ok(match (s.kind, s.width) {
            (Float, 4) => "f32",
            (Float, 2) => "f16",
            (Sint, 4) => "i32",
            (Uint, 4) => "u32",
            (Bool, _) => "bool",
            _ => return Err(err("call", format!("{function}: unsupported scalar {s:?}"))),
        })
    };
    let t = &module.types[ty];
    Ok(match &t.inner {
        TypeInner::Scalar(s) => scalar(*s)?.to_string(),
        TypeInner::Vector { size, scalar: s } => format!("vec{}<{}>", *size as u8, scalar(*s)?),
        TypeInner::Matrix {
            columns,
            rows,
            scalar: s,
        } => format!("mat{}x{}<{}>", *columns as u8, *rows as u8, scalar(*s)?),
        TypeInner::Struct { .. } => t
            .name
            .clone()
            .ok_or_else(|| err("call", format!("{function}: anonymous struct argument")))?,
        TypeInner::Array {
            base,
            size: naga::ArraySize::Constant(n),
            ..
        } => format!("array<{}, {n}>", wgsl_type_name(module, *base, function)?),
        other => {
            return Err(err(
                "call",
                format!("{function}: argument type {other:?} cannot be zero-constructed"),
            ));
        }
    })
}
