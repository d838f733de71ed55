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
