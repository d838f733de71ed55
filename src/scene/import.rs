//! The shipped files in the forms shader importers read: naga_oil modules (Bevy 0.19's loader)
//! and WESL modules. Plain text, no dependency: available on default features.

use crate::wgsl::WgslFile;

/// A shipped file as a naga_oil module: `#define_import_path prepass::<stem>` followed by the
/// file's text. Register it with `naga_oil::compose::Composer::add_composable_module` and import
/// with `#import prepass::<stem>::<function>` (or `#import prepass::<stem>` and `<stem>::<fn>`).
pub fn naga_oil_module(file: &WgslFile) -> String {
    let stem = file.name.trim_end_matches(".wgsl");
    format!("#define_import_path prepass::{stem}\n\n{}", file.source)
}

/// A shipped file as a WESL module: plain WGSL is valid WESL, so the text is the file itself,
/// placed at `<package root>/<stem>.wesl` and imported with `import package::<stem>::<fn>;`
/// (or `import prepass::<stem>::<fn>;` when mounted as a package named `prepass`).
pub fn wesl_module(file: &WgslFile) -> (String, &'static str) {
    (file.name.replace(".wgsl", ".wesl"), file.source)
}

/// The manifest of the WESL package [`wesl_package`] lays out: wesl 0.4's `wesl.toml`
/// (`edition`, and `root`, the folder holding the modules).
pub const WESL_TOML: &str = "edition = \"2026_pre\"\nroot = \"./shaders\"\n";

/// Every shipped file as a WESL package named by its folder (`prepass/` in the README): paths
/// relative to the package folder and their text, `wesl.toml` ([`WESL_TOML`]) first, then
/// `shaders/<stem>.wesl` per file. Write them out, point `wesl::PkgBuilder::scan_toml` (or an
/// application's `[dependencies]`) at the folder, and import `prepass::<stem>::<fn>`.
/// `tests/imports.rs` compiles an application against exactly this package.
pub fn wesl_package() -> Vec<(String, &'static str)> {
    std::iter::once(("wesl.toml".to_string(), WESL_TOML))
        .chain(crate::wgsl::FILES.iter().map(|f| {
            let (name, text) = wesl_module(f);
            (format!("shaders/{name}"), text)
        }))
        .collect()
}
