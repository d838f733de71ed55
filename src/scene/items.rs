//! The shipped WGSL files cut into top-level items by their text alone (no naga): what
//! [`Scene::wgsl`](super::Scene::wgsl) composes on default features.
//!
//! The shipped files keep one layout, which `tests/scene.rs` checks by comparing this
//! composition with naga's ([`super::Library`], feature `validate`) for every distinct scene:
//! each item starts at column 0 with `fn`, `const`, `struct`, `var`, `override` or `alias`,
//! its comment block directly above it, and ends where its braces close or at its `;`. An
//! item uses every other item whose name appears in its text outside comments (shipped names
//! are unique and prefixed, so a match is a use).

use crate::wgsl::{FILES, WgslFile};
use std::collections::{BTreeSet, HashMap};
use std::sync::OnceLock;

/// One top-level item of a shipped file, cut from its text.
#[derive(Clone, Debug)]
pub(crate) struct TextItem {
    pub name: &'static str,
    pub file: &'static str,
    /// The item with its comment block.
    pub text: &'static str,
}

/// The byte offset where the comment lines directly above `start` begin.
pub(crate) fn leading_comment(source: &str, start: usize) -> usize {
    let mut begin = start;
    let mut lines: Vec<&str> = source[..start].split_inclusive('\n').collect();
    // The item starts at a line start; drop the (empty) partial line before it, if any.
    if lines.last().is_some_and(|l| !l.ends_with('\n')) {
        lines.pop();
    }
    for line in lines.iter().rev() {
        if line.trim_start().starts_with("//") {
            begin -= line.len();
        } else {
            break;
        }
    }
    begin
}

/// The identifier tokens of WGSL text, comments skipped.
pub(crate) fn identifiers(text: &str) -> impl Iterator<Item = &str> {
    text.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .flat_map(|l| l.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')))
        .filter(|t| t.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_'))
}

/// The name a top-level line declares, if it starts an item.
fn declared_name(line: &str) -> Option<&str> {
    let rest = ["fn ", "const ", "struct ", "override ", "alias "]
        .iter()
        .find_map(|kw| line.strip_prefix(kw))
        .or_else(|| {
            let r = line.strip_prefix("var")?;
            match r.strip_prefix('<') {
                Some(r) => Some(&r[r.find('>')? + 1..]),
                None => r.starts_with(' ').then_some(r),
            }
        })?
        .trim_start();
    let end = rest
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(rest.len());
    (end > 0).then(|| &rest[..end])
}

/// The end (exclusive) of the item starting at `start`: where its brackets close again after
/// a `}` (functions, structs) or at a `;` outside brackets (the other declarations).
fn item_end(source: &str, start: usize) -> usize {
    let mut depth = 0i32;
    let mut in_comment = false;
    let bytes = source.as_bytes();
    let mut i = start;
    while i < bytes.len() {
        let c = bytes[i];
        if in_comment {
            in_comment = c != b'\n';
        } else if c == b'/' && bytes.get(i + 1) == Some(&b'/') {
            in_comment = true;
        } else if matches!(c, b'{' | b'(' | b'[') {
            depth += 1;
        } else if matches!(c, b'}' | b')' | b']') {
            depth -= 1;
            if depth == 0 && c == b'}' {
                return i + 1;
            }
        } else if c == b';' && depth == 0 {
            return i + 1;
        }
        i += 1;
    }
    source.len()
}

/// Every top-level item of `file`, in source order.
pub(crate) fn items_of(file: &'static WgslFile) -> Vec<TextItem> {
    let src = file.source;
    let mut items = Vec::new();
    let mut offset = 0;
    for line in src.split_inclusive('\n') {
        if let Some(name) = declared_name(line) {
            let end = item_end(src, offset);
            items.push(TextItem {
                name,
                file: file.name,
                text: &src[leading_comment(src, offset)..end],
            });
        }
        offset += line.len();
    }
    items
}

/// The shipped items in registry and source order, each with the items its text names.
struct Graph {
    items: Vec<TextItem>,
    index: HashMap<&'static str, usize>,
    uses: Vec<Vec<usize>>,
}

/// Cut once per process: the files are static, and a renderer (or the scene tests, once per
/// distinct root set) may compose many scenes.
fn graph() -> &'static Graph {
    static GRAPH: OnceLock<Graph> = OnceLock::new();
    GRAPH.get_or_init(|| {
        let items: Vec<TextItem> = FILES.iter().flat_map(items_of).collect();
        let index: HashMap<&'static str, usize> =
            items.iter().enumerate().map(|(k, i)| (i.name, k)).collect();
        let uses = items
            .iter()
            .map(|item| {
                identifiers(item.text)
                    .filter(|id| *id != item.name)
                    .filter_map(|id| index.get(id).copied())
                    .collect()
            })
            .collect();
        Graph { items, index, uses }
    })
}

/// The module holding exactly what `roots` reach, in registry and source order, each item
/// after its comment block: the same text as the naga composer's `Library::compose`. `Err`
/// names a root no shipped file defines.
pub(crate) fn compose<'a>(roots: impl IntoIterator<Item = &'a str>) -> Result<String, String> {
    let g = graph();
    let mut keep = BTreeSet::new();
    let mut stack = Vec::new();
    for r in roots {
        stack.push(*g.index.get(r).ok_or_else(|| r.to_string())?);
    }
    while let Some(i) = stack.pop() {
        if keep.insert(i) {
            stack.extend(g.uses[i].iter().filter(|j| !keep.contains(*j)));
        }
    }
    let mut out = String::from("// Composed by prepass::scene from the shipped WGSL files.\n");
    let mut file = "";
    for i in keep {
        let item = &g.items[i];
        if item.file != file {
            file = item.file;
            out.push_str(&format!("\n// ---- from wgsl/{file} ----\n"));
        }
        out.push('\n');
        out.push_str(item.text);
        out.push('\n');
    }
    Ok(out)
}
