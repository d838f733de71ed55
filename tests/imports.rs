//! Importing prepass into other shader systems, the way their users do.
//!
//! - **Bevy 0.19** (naga_oil 0.22 on naga 29): every shipped file, in the form
//!   [`prepass::scene::naga_oil_module`] gives, goes through a model of Bevy 0.19's shader cache
//!   (`crates/bevy_shader/src/{shader,shader_cache}.rs` and
//!   `crates/bevy_render/src/render_resource/pipeline_cache.rs` at tag v0.19.1): the same
//!   `ComposableModuleDescriptor` / `NagaModuleDescriptor` fields, imports found by
//!   `get_preprocessor_data` and added recursively, the global shader def
//!   `AVAILABLE_STORAGE_BUFFER_BINDINGS` on every shader, the pipeline's defs on the entry
//!   shader, the debug/release composer choice. A `#define_import_path` light-pre-pass shader
//!   imports five files, by item list and module-qualified, and its module passes naga 29's
//!   validator as wgpu 29 runs it.
//! - **WESL** (wesl 0.4.0): the files, from [`prepass::scene::wesl_module`], laid out as a WESL
//!   package as `wesl.toml` documents it (`<package>/wesl.toml` with `edition = "2026_pre"`,
//!   modules under its `root`, `./shaders`), read by `PkgBuilder::scan_toml`, mounted as package
//!   `prepass` the way `wesl_pkg!` does at build time, and imported by an application's
//!   `package::main` as `import prepass::normal_oct::decode_normal_oct24;`. The WGSL out passes
//!   naga 29's validator.
//!
//! Not built here (rustc 1.95): wesl 0.4.1 and 0.4.2 declare `rust-version = "1.96.0"`, 0.4.3,
//! 0.4.4, 0.5.0 and 0.6.0 `1.97.1`; cargo refuses them ("rustc 1.95.0 is not supported by the
//! following packages: wesl@0.6.0 requires rustc 1.97.1, wesl-core@0.1.0 requires rustc 1.97.1,
//! wesl-macros@0.6.0 …, wgsl-parse@0.6.0 …, wgsl-types@0.6.0 …"; `cargo check
//! --ignore-rust-version` does get through wesl 0.6.0 on 1.95, but a build that needs that flag
//! is not one we ship). Bevy's main branch (0.20.0-dev, `rust-version = "1.96.0"`, checked at
//! commit 4805ca79) replaced naga_oil with WESL through wesl 0.4.2 (itself 1.96, and `^0.4.2`
//! resolves to 0.4.4's 1.97.1), so cargo refuses it and its shader cache on this toolchain too.

use naga_29 as naga;
use naga_oil::compose::{
    ComposableModuleDescriptor, Composer, ImportDefinition, NagaModuleDescriptor, ShaderDefValue,
    ShaderLanguage, ShaderType, get_preprocessor_data,
};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// Validate a module as wgpu does before creating a shader module from it.
fn validate(module: &naga::Module, capabilities: naga::valid::Capabilities) -> Result<(), String> {
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
        .validate(module)
        .map(|_| ())
        .map_err(|e| {
            let mut message = e.to_string();
            let mut source = std::error::Error::source(&e);
            while let Some(s) = source {
                message.push_str(&format!(": {s}"));
                source = s.source();
            }
            message
        })
}

fn function_names(module: &naga::Module) -> Vec<String> {
    module
        .functions
        .iter()
        .filter_map(|(_, f)| f.name.clone())
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Bevy 0.19: a model of the part of its shader cache that talks to naga_oil, written from
// reading it (the same naga_oil calls with the same descriptor fields, in the same order).

/// Bevy's `ShaderImport`: where a shader can be imported from.
#[derive(Clone, Debug, PartialEq)]
enum ShaderImport {
    AssetPath(String),
    Custom(String),
}

impl ShaderImport {
    /// `ShaderImport::module_name`: the name naga_oil knows the module by.
    fn module_name(&self) -> String {
        match self {
            ShaderImport::AssetPath(s) => format!("\"{s}\""),
            ShaderImport::Custom(s) => s.clone(),
        }
    }
}

/// The fields of Bevy's `Shader` asset the composer reads.
struct BevyShader {
    path: String,
    source: String,
    import_path: ShaderImport,
    imports: Vec<ShaderImport>,
    additional_imports: Vec<ImportDefinition>,
    shader_defs: Vec<(String, ShaderDefValue)>,
}

impl BevyShader {
    /// `Shader::from_wgsl`: the import path and imports come from naga_oil's preprocessor
    /// (`Shader::preprocess`); a quoted import is an asset path.
    fn from_wgsl(source: String, path: &str) -> Self {
        let (import_path, imports, _) = get_preprocessor_data(&source);
        let import_path = import_path
            .map(ShaderImport::Custom)
            .unwrap_or_else(|| ShaderImport::AssetPath(path.to_owned()));
        let imports = imports
            .into_iter()
            .map(|i| match i.import.strip_prefix('"') {
                Some(rest) => {
                    ShaderImport::AssetPath(rest.chars().take_while(|c| *c != '"').collect())
                }
                None => ShaderImport::Custom(i.import),
            })
            .collect();
        BevyShader {
            path: path.to_owned(),
            source,
            import_path,
            imports,
            additional_imports: Vec::new(),
            shader_defs: Vec::new(),
        }
    }

    /// `impl From<&Shader> for ComposableModuleDescriptor`.
    fn composable(&self) -> ComposableModuleDescriptor<'_> {
        ComposableModuleDescriptor {
            source: &self.source,
            file_path: &self.path,
            language: ShaderLanguage::Wgsl,
            additional_imports: &self.additional_imports,
            shader_defs: self.shader_defs.iter().cloned().collect(),
            as_name: match &self.import_path {
                ShaderImport::AssetPath(p) => Some(format!("\"{p}\"")),
                ShaderImport::Custom(_) => None,
            },
        }
    }
}

/// `PipelineCache::new`'s global shader defs on a native target: only
/// `AVAILABLE_STORAGE_BUFFER_BINDINGS`, the device's `max_storage_buffers_per_shader_stage`
/// (8, wgpu's default limit). WebGL builds add `NO_ARRAY_TEXTURES_SUPPORT`,
/// `NO_CUBE_ARRAY_TEXTURES_SUPPORT` and `SIXTEEN_BYTE_ALIGNMENT`; iOS simulators
/// `NO_CUBE_ARRAY_TEXTURES_SUPPORT`.
fn global_shader_defs() -> Vec<(String, ShaderDefValue)> {
    vec![(
        "AVAILABLE_STORAGE_BUFFER_BINDINGS".to_owned(),
        ShaderDefValue::UInt(8),
    )]
}

/// Bevy's `ShaderCache`, reduced to composing.
struct BevyShaderCache {
    composer: Composer,
    shaders: Vec<BevyShader>,
}

impl BevyShaderCache {
    /// `ShaderCache::new`: a validating composer in debug builds, a non-validating one in
    /// release (wgpu validates the module then), with the device's capabilities (none of the
    /// optional ones here).
    fn new() -> Self {
        Self::with_composer(if cfg!(debug_assertions) {
            Composer::default()
        } else {
            Composer::non_validating()
        })
    }

    fn with_composer(composer: Composer) -> Self {
        BevyShaderCache {
            composer: composer.with_capabilities(naga::valid::Capabilities::empty()),
            shaders: Vec::new(),
        }
    }

    /// `PipelineCache::extract_shaders` + `ShaderCache::set_shader`: every shader gets the
    /// global defs.
    fn set_shader(&mut self, mut shader: BevyShader) -> usize {
        shader.shader_defs.extend(global_shader_defs());
        self.shaders.push(shader);
        self.shaders.len() - 1
    }

    /// `ShaderCache::add_import_to_composer`: add an import's module after its own imports.
    fn add_import(&mut self, import: &ShaderImport, importer: &str) -> Result<(), String> {
        if self.composer.contains_module(&import.module_name()) {
            return Ok(());
        }
        let index = self
            .shaders
            .iter()
            .position(|s| s.import_path == *import)
            .ok_or_else(|| {
                format!(
                    "{importer}: import `{}` is not registered (no shader has that import path)",
                    import.module_name()
                )
            })?;
        let imports = self.shaders[index].imports.clone();
        let path = self.shaders[index].path.clone();
        for i in &imports {
            self.add_import(i, &path)?;
        }
        let shader = &self.shaders[index];
        if let Err(e) = self.composer.add_composable_module(shader.composable()) {
            return Err(format!(
                "{}: naga_oil rejected module `{}` (imported by {importer}):\n{}",
                shader.path,
                import.module_name(),
                e.emit_to_string(&self.composer)
            ));
        }
        Ok(())
    }

    /// `ShaderCache::get` for a WGSL shader: add its imports, then make the naga module with the
    /// pipeline's defs chained with the shader's own.
    fn get(
        &mut self,
        id: usize,
        pipeline_defs: &[(String, ShaderDefValue)],
    ) -> Result<naga::Module, String> {
        let imports = self.shaders[id].imports.clone();
        let path = self.shaders[id].path.clone();
        for i in &imports {
            self.add_import(i, &path)?;
        }
        let shader = &self.shaders[id];
        let shader_defs = pipeline_defs
            .iter()
            .chain(shader.shader_defs.iter())
            .cloned()
            .collect::<HashMap<_, _>>();
        self.composer
            .make_naga_module(NagaModuleDescriptor {
                source: &shader.source,
                file_path: &shader.path,
                shader_type: ShaderType::Wgsl,
                shader_defs,
                ..Default::default()
            })
            .map_err(|e| format!("{}: {}", shader.path, e.emit_to_string(&self.composer)))
    }
}

/// A light-pre-pass shader a Bevy 0.19 user writes against prepass: a `#define_import_path`
/// like a material shader library, item-list imports, a module import used qualified
/// (`linear_depth::…`), a pipeline shader def and Bevy's global one.
const BEVY_USER_SHADER: &str = "\
#define_import_path my_game::light_prepass

#import prepass::normal_oct::{encode_normal_oct24, decode_normal_oct24}
#import prepass::linear_depth
#import prepass::position::{frustum_ray_rh, ndc_from_uv, view_position}
#import prepass::roughness::{encode_log_roughness, decode_log_roughness}
#import prepass::lpp::lpp_point_light

struct View {
    // xyz: the `k` of view_z_from_reversed_depth_consts, from Projection::reversed_depth_consts.
    depth_consts: vec4<f32>,
    tan_half_fov: vec2<f32>,
    size: vec2<f32>,
}

struct PointLight {
    position: vec3<f32>,
    radius: f32,
    colour: vec3<f32>,
}

const MAX_POWER: f32 = 2048.0;

@group(0) @binding(0) var<uniform> view: View;
@group(0) @binding(1) var depth_texture: texture_depth_2d;
@group(0) @binding(2) var gbuffer: texture_2d<u32>;
@group(0) @binding(3) var<uniform> light: PointLight;

@fragment
fn light_fragment(@builtin(position) frag: vec4<f32>) -> @location(0) vec4<f32> {
    let texel = vec2<i32>(frag.xy);
    let vz = linear_depth::view_z_from_reversed_depth_consts(textureLoad(depth_texture, texel, 0), view.depth_consts.xyz);
    let p = view_position(frustum_ray_rh(ndc_from_uv(frag.xy / view.size), view.tan_half_fov), vz);
    let g = textureLoad(gbuffer, texel, 0);
    let n = decode_normal_oct24(g.x);
    let power = decode_log_roughness(g.y, MAX_POWER);
#ifdef PREPASS_POINT_LIGHT
    return lpp_point_light(n, normalize(-p), light.position - p, vec4<f32>(light.colour, light.radius), power);
#else
    return vec4<f32>(n * power, vz);
#endif
}

#if AVAILABLE_STORAGE_BUFFER_BINDINGS >= 1
@group(0) @binding(4) var<storage, read_write> baked: array<vec2<u32>>;

@compute @workgroup_size(64)
fn bake_gbuffer(@builtin(global_invocation_id) id: vec3<u32>) {
    let t = f32(id.x) / 64.0;
    let n = normalize(vec3<f32>(t, 1.0 - t, 0.5));
    baked[id.x] = vec2<u32>(encode_normal_oct24(n), encode_log_roughness(1.0 + 100.0 * t, MAX_POWER));
}
#endif
";

#[test]
fn bevy_0_19_naga_oil_imports_prepass() {
    let mut cache = BevyShaderCache::new();
    // A plugin registers every shipped file as a `Shader` asset (`Shader::from_wgsl`).
    for f in prepass::wgsl::FILES {
        let shader = BevyShader::from_wgsl(
            prepass::scene::naga_oil_module(f),
            &format!("embedded://prepass/{}", f.name),
        );
        let stem = f.name.trim_end_matches(".wgsl");
        assert_eq!(
            shader.import_path,
            ShaderImport::Custom(format!("prepass::{stem}")),
            "{}: naga_oil reads another import path",
            f.name
        );
        cache.set_shader(shader);
    }
    let user = cache.set_shader(BevyShader::from_wgsl(
        BEVY_USER_SHADER.to_owned(),
        "shaders/light_prepass.wgsl",
    ));
    let expected_imports = ["normal_oct", "linear_depth", "position", "roughness", "lpp"]
        .map(|m| ShaderImport::Custom(format!("prepass::{m}")));
    for i in &expected_imports {
        assert!(
            cache.shaders[user].imports.contains(i),
            "shaders/light_prepass.wgsl: naga_oil's preprocessor missed import {i:?}: {:?}",
            cache.shaders[user].imports
        );
    }

    // The specialised pipeline's defs (`FragmentState::shader_defs`).
    let pipeline_defs = [("PREPASS_POINT_LIGHT".to_owned(), ShaderDefValue::Bool(true))];
    let module = cache
        .get(user, &pipeline_defs)
        .unwrap_or_else(|e| panic!("Bevy 0.19 composition failed: {e}"));
    // wgpu validates a `ShaderSource::Naga` module with the device's capabilities. On failure,
    // compose again as a debug build does (validating composer) for an error with file and line.
    if let Err(e) = validate(&module, cache.composer.capabilities) {
        let mut debug = BevyShaderCache::with_composer(Composer::default());
        for s in cache.shaders.drain(..) {
            debug.shaders.push(s);
        }
        let located = debug.get(user, &pipeline_defs).err().unwrap_or_default();
        panic!("shaders/light_prepass.wgsl composed with prepass: {e}\n{located}");
    }

    let entries: Vec<_> = module
        .entry_points
        .iter()
        .map(|e| (e.name.as_str(), e.stage))
        .collect();
    assert!(
        entries.contains(&("light_fragment", naga::ShaderStage::Fragment))
            && entries.contains(&("bake_gbuffer", naga::ShaderStage::Compute)),
        "entry points (the `#if AVAILABLE_STORAGE_BUFFER_BINDINGS` one needs Bevy's global def): {entries:?}"
    );

    let functions = function_names(&module);
    for (m, item) in [
        ("normal_oct", "encode_normal_oct24"),
        ("normal_oct", "decode_normal_oct24"),
        ("linear_depth", "view_z_from_reversed_depth_consts"),
        ("position", "frustum_ray_rh"),
        ("position", "view_position"),
        ("roughness", "encode_log_roughness"),
        ("roughness", "decode_log_roughness"),
        ("lpp", "lpp_point_light"),
    ] {
        let name = Composer::decorated_name(Some(&format!("prepass::{m}")), item);
        assert!(
            functions.contains(&name),
            "prepass::{m}::{item} missing from the composed module: {functions:?}"
        );
    }
    // Every shipped file composes, whichever another shader imports.
    for f in prepass::wgsl::FILES {
        let import = ShaderImport::Custom(format!("prepass::{}", f.name.trim_end_matches(".wgsl")));
        cache
            .add_import(&import, "another shader")
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(
            cache.composer.contains_module(&import.module_name()),
            "{}",
            f.name
        );
    }
}

// ---------------------------------------------------------------------------------------------
// WESL: a package in wesl's documented layout.

/// `<dir>/wesl.toml` and the modules under its root (`./shaders`, the default).
fn write_wesl_package(dir: &Path, manifest: &str, modules: &[(String, &str)]) {
    let shaders = dir.join("shaders");
    std::fs::create_dir_all(&shaders).unwrap();
    std::fs::write(dir.join("wesl.toml"), manifest).unwrap();
    for (file, text) in modules {
        std::fs::write(shaders.join(file), text).unwrap();
    }
}

/// What `PkgBuilder::build_artifact` writes and `wesl_pkg!` includes, built at run time.
fn codegen_module(m: wesl::Module) -> &'static wesl::CodegenModule {
    let submodules: Vec<&'static wesl::CodegenModule> =
        m.submodules.into_iter().map(codegen_module).collect();
    Box::leak(Box::new(wesl::CodegenModule {
        name: String::leak(m.name),
        source: String::leak(m.source),
        submodules: Vec::leak(submodules),
    }))
}

/// An application's shader: `import` statements first, then declarations.
const WESL_USER_SHADER: &str = "\
import prepass::normal_oct::{encode_normal_oct24, decode_normal_oct24};
import prepass::linear_depth::view_z_from_reversed_depth_consts;
import prepass::position::{frustum_ray_rh, view_position};
import prepass::roughness::decode_log_roughness;
import prepass::lpp;

@group(0) @binding(0) var<uniform> depth_consts: vec4<f32>;
@group(0) @binding(1) var<storage, read_write> out: array<vec4<f32>>;

@compute @workgroup_size(1)
fn main() {
    let n = decode_normal_oct24(encode_normal_oct24(vec3<f32>(0.0, 0.6, 0.8)));
    let vz = view_z_from_reversed_depth_consts(0.5, depth_consts.xyz);
    let p = view_position(frustum_ray_rh(vec2<f32>(0.25, -0.5), vec2<f32>(1.0, 0.75)), vz);
    let power = decode_log_roughness(77u, 2048.0);
    out[0] = lpp::lpp_point_light(n, normalize(-p), vec3<f32>(1.0, 2.0, -3.0) - p, vec4<f32>(1.0, 1.0, 1.0, 10.0), power);
}
";

#[test]
fn wesl_package_imports_prepass() {
    let root = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("imports_wesl");
    let _ = std::fs::remove_dir_all(&root);
    // The library: `prepass/wesl.toml` + `prepass/shaders/<stem>.wesl`, module `prepass::<stem>`.
    let library = root.join("prepass");
    let modules: Vec<_> = prepass::wgsl::FILES
        .iter()
        .map(prepass::scene::wesl_module)
        .collect();
    // The package exactly as prepass lays it out (`prepass::scene::wesl_package`).
    for (path, text) in prepass::scene::wesl_package() {
        let file = library.join(path);
        std::fs::create_dir_all(file.parent().unwrap()).unwrap();
        std::fs::write(file, text).unwrap();
    }
    // The application: its own package, depending on the library by path.
    let app = root.join("app");
    write_wesl_package(
        &app,
        "edition = \"2026_pre\"\nroot = \"./shaders\"\n\n[dependencies]\nprepass = { path = \"../prepass\" }\n",
        &[("main.wesl".to_owned(), WESL_USER_SHADER)],
    );
    wesl::WeslToml::from_file(app.join("wesl.toml"))
        .unwrap_or_else(|e| panic!("{}: {e}", app.join("wesl.toml").display()));

    let pkg = wesl::PkgBuilder::new("prepass")
        .scan_toml(&library)
        .unwrap_or_else(|e| panic!("{}: {e}", library.join("wesl.toml").display()));
    assert_eq!(pkg.root.name, "prepass");
    let mut found: Vec<_> = pkg.root.submodules.iter().map(|m| m.name.clone()).collect();
    found.sort();
    let mut shipped: Vec<_> = modules
        .iter()
        .map(|(f, _)| f.trim_end_matches(".wesl").to_owned())
        .collect();
    shipped.sort();
    assert_eq!(
        found,
        shipped,
        "{}: modules the package holds",
        library.display()
    );
    let package: &'static wesl::CodegenPkg = Box::leak(Box::new(wesl::CodegenPkg {
        crate_name: String::leak(pkg.crate_name),
        root: codegen_module(pkg.root),
        dependencies: &[],
    }));

    let mut compiler = wesl::Wesl::new(app.join("shaders"));
    compiler.add_package(package);
    let main: wesl::ModulePath = "package::main".parse().unwrap();
    let wgsl = compiler
        .compile(&main)
        .unwrap_or_else(|e| panic!("{}: {e}", app.join("shaders/main.wesl").display()))
        .to_string();

    let module = naga::front::wgsl::parse_str(&wgsl).unwrap_or_else(|e| {
        panic!(
            "wesl's output does not parse: {}\n{wgsl}",
            e.emit_to_string(&wgsl)
        )
    });
    validate(&module, naga::valid::Capabilities::empty())
        .unwrap_or_else(|e| panic!("wesl's output of app/shaders/main.wesl: {e}\n{wgsl}"));
    let functions = function_names(&module);
    for (m, item) in [
        ("normal_oct", "encode_normal_oct24"),
        ("normal_oct", "decode_normal_oct24"),
        ("linear_depth", "view_z_from_reversed_depth_consts"),
        ("position", "frustum_ray_rh"),
        ("position", "view_position"),
        ("roughness", "decode_log_roughness"),
        ("lpp", "lpp_point_light"),
    ] {
        let path: wesl::ModulePath = format!("prepass::{m}").parse().unwrap();
        let name = wesl::Mangler::mangle(&wesl::EscapeMangler, &path, item);
        assert!(
            functions.contains(&name),
            "prepass::{m}::{item} ({name}) missing from wesl's output: {functions:?}"
        );
    }
    assert!(
        module.entry_points.iter().any(|e| e.name == "main"),
        "{wgsl}"
    );
}
