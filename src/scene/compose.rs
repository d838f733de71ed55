//! Compose one WGSL module holding only what a set of root functions reaches (feature
//! `validate`).
//!
//! Every shipped file is parsed by naga on its own; each top-level item (function, constant,
//! struct) is cut from the original text by naga's span, together with the comment block right
//! above it, and its dependencies are read from naga's IR: calls in the function body (any
//! nesting), constants its expressions or other constants use, and named types of its
//! arguments, result, locals and constructions. The module is the dependency closure of the
//! roots, emitted in the registry's file order and each file's source order, so adding a root
//! only inserts items: the text of the others never changes.

use super::items::{identifiers, leading_comment};
use crate::wgsl::{FILES, WgslError, WgslFile, parse_and_validate};
use naga::{Block, Expression, Handle, Module, Statement, Type, TypeInner};
use std::collections::{BTreeSet, HashMap};

/// One top-level item of a shipped WGSL file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Item {
    /// The item's name (unique across all shipped files).
    pub name: String,
    /// What it is: `"fn"`, `"const"` or `"struct"`.
    pub kind: &'static str,
    /// The file it comes from.
    pub file: &'static str,
    /// Its text, with the comment block directly above it.
    pub text: String,
    /// Names of the items it uses directly.
    pub uses: BTreeSet<String>,
}

/// Every item of every shipped file, in registry and source order.
#[derive(Clone, Debug)]
pub struct Library {
    items: Vec<Item>,
    index: HashMap<String, usize>,
}

/// Why composition failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ComposeError {
    /// A shipped file (or the composed module) failed naga.
    Wgsl {
        /// The file, or `"<composed>"`.
        file: String,
        /// naga's error.
        error: WgslError,
    },
    /// Two files define the same name, so they cannot be combined.
    DuplicateName {
        /// The name.
        name: String,
        /// The two files.
        files: (String, String),
    },
    /// A root names no item.
    UnknownRoot(String),
}

impl std::fmt::Display for ComposeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Wgsl { file, error } => write!(f, "{file}: {error}"),
            Self::DuplicateName { name, files } => write!(
                f,
                "`{name}` is defined in both {} and {}: shipped names must be unique",
                files.0, files.1
            ),
            Self::UnknownRoot(r) => write!(f, "no shipped WGSL function or item named `{r}`"),
        }
    }
}

impl std::error::Error for ComposeError {}

fn walk_calls(block: &Block, out: &mut Vec<Handle<naga::Function>>) {
    for stmt in block.iter() {
        match stmt {
            Statement::Call { function, .. } => out.push(*function),
            Statement::Block(b) => walk_calls(b, out),
            Statement::If { accept, reject, .. } => {
                walk_calls(accept, out);
                walk_calls(reject, out);
            }
            Statement::Switch { cases, .. } => cases.iter().for_each(|c| walk_calls(&c.body, out)),
            Statement::Loop {
                body, continuing, ..
            } => {
                walk_calls(body, out);
                walk_calls(continuing, out);
            }
            _ => {}
        }
    }
}

/// Named struct types reachable from `ty` (through arrays and members).
fn named_types(module: &Module, ty: Handle<Type>, out: &mut BTreeSet<String>) {
    let t = &module.types[ty];
    match &t.inner {
        TypeInner::Struct { members, .. } => {
            if let Some(n) = &t.name
                && out.insert(n.clone())
            {
                for m in members {
                    named_types(module, m.ty, out);
                }
            }
        }
        TypeInner::Array { base, .. } => named_types(module, *base, out),
        _ => {}
    }
}

fn expression_uses(
    module: &Module,
    e: &Expression,
    consts: &mut BTreeSet<String>,
    types: &mut BTreeSet<String>,
) {
    match e {
        Expression::Constant(c) => {
            if let Some(n) = &module.constants[*c].name {
                consts.insert(n.clone());
            }
        }
        Expression::Compose { ty, .. } | Expression::ZeroValue(ty) => {
            named_types(module, *ty, types)
        }
        _ => {}
    }
}

fn items_of(file: &WgslFile) -> Result<Vec<Item>, ComposeError> {
    let checked = parse_and_validate(file.source).map_err(|error| ComposeError::Wgsl {
        file: file.name.to_string(),
        error,
    })?;
    let m = &checked.module;
    let src = file.source;
    let cut = |span: naga::Span| -> (usize, String) {
        let r = span.to_range().unwrap_or(0..0);
        let begin = leading_comment(src, r.start);
        (r.start, src[begin..r.end].to_string())
    };
    let mut items: Vec<(usize, Item)> = Vec::new();
    for (h, c) in m.constants.iter() {
        let Some(name) = &c.name else { continue };
        let (mut consts, mut types) = (BTreeSet::new(), BTreeSet::new());
        collect_global(m, c.init, &mut consts, &mut types);
        named_types(m, c.ty, &mut types);
        let (at, text) = cut(m.constants.get_span(h));
        items.push((
            at,
            Item {
                name: name.clone(),
                kind: "const",
                file: file.name,
                text,
                uses: consts.into_iter().chain(types).collect(),
            },
        ));
    }
    for (h, t) in m.types.iter() {
        let (Some(name), TypeInner::Struct { members, .. }) = (&t.name, &t.inner) else {
            continue;
        };
        let mut types = BTreeSet::new();
        for mem in members {
            named_types(m, mem.ty, &mut types);
        }
        let (at, text) = cut(m.types.get_span(h));
        items.push((
            at,
            Item {
                name: name.clone(),
                kind: "struct",
                file: file.name,
                text,
                uses: types,
            },
        ));
    }
    for (h, f) in m.functions.iter() {
        let Some(name) = &f.name else { continue };
        let (mut consts, mut types) = (BTreeSet::new(), BTreeSet::new());
        for (_, e) in f.expressions.iter() {
            expression_uses(m, e, &mut consts, &mut types);
        }
        for a in &f.arguments {
            named_types(m, a.ty, &mut types);
        }
        if let Some(r) = &f.result {
            named_types(m, r.ty, &mut types);
        }
        for (_, l) in f.local_variables.iter() {
            named_types(m, l.ty, &mut types);
        }
        let mut calls = Vec::new();
        walk_calls(&f.body, &mut calls);
        let callees = calls
            .into_iter()
            .filter_map(|c| m.functions[c].name.clone());
        let (at, text) = cut(m.functions.get_span(h));
        items.push((
            at,
            Item {
                name: name.clone(),
                kind: "fn",
                file: file.name,
                text,
                uses: consts.into_iter().chain(types).chain(callees).collect(),
            },
        ));
    }
    // Abstract-typed constants (`const K = 1.0;`) are folded away by naga and never reach the
    // IR, and module-scope `var<private>` tables are globals, not items above: take every
    // top-level declaration the list lacks from the text, up to its `;`.
    let known: BTreeSet<String> = items.iter().map(|(_, i)| i.name.clone()).collect();
    let mut offset = 0;
    for line in src.split_inclusive('\n') {
        if let Some(rest) = top_level_declaration(line) {
            let name: String = rest
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() && !known.contains(&name) {
                let end = src[offset..]
                    .find(';')
                    .map_or(src.len(), |e| offset + e + 1);
                let begin = leading_comment(src, offset);
                items.push((
                    offset,
                    Item {
                        name,
                        kind: "const",
                        file: file.name,
                        text: src[begin..end].to_string(),
                        uses: BTreeSet::new(),
                    },
                ));
            }
        }
        offset += line.len();
    }
    // naga folds `const` references into literals inside function bodies, so the IR alone can
    // miss a constant a function uses: also take every identifier of the item's text that names
    // a constant or struct of this file (shipped names are unique, so a match is a use).
    let declared: BTreeSet<String> = items
        .iter()
        .filter(|(_, i)| i.kind != "fn")
        .map(|(_, i)| i.name.clone())
        .collect();
    for (_, item) in items.iter_mut() {
        for ident in identifiers(&item.text) {
            if ident != item.name && declared.contains(ident) {
                item.uses.insert(ident.to_string());
            }
        }
    }
    items.sort_by_key(|(at, _)| *at);
    Ok(items.into_iter().map(|(_, i)| i).collect())
}

/// The text after the keyword of a top-level `const`, `override`, `alias` or `var<…>` line.
fn top_level_declaration(line: &str) -> Option<&str> {
    for kw in ["const ", "override ", "alias "] {
        if let Some(rest) = line.strip_prefix(kw) {
            return Some(rest.trim_start());
        }
    }
    let rest = line.strip_prefix("var")?;
    let rest = match rest.strip_prefix('<') {
        Some(r) => &r[r.find('>')? + 1..],
        None => rest,
    };
    rest.starts_with(char::is_whitespace)
        .then(|| rest.trim_start())
}

fn collect_global(
    m: &Module,
    e: Handle<Expression>,
    consts: &mut BTreeSet<String>,
    types: &mut BTreeSet<String>,
) {
    let expr = &m.global_expressions[e];
    expression_uses(m, expr, consts, types);
    match expr {
        Expression::Compose { components, .. } => {
            for c in components {
                collect_global(m, *c, consts, types);
            }
        }
        Expression::Binary { left, right, .. } => {
            collect_global(m, *left, consts, types);
            collect_global(m, *right, consts, types);
        }
        Expression::Unary { expr, .. } | Expression::As { expr, .. } => {
            collect_global(m, *expr, consts, types)
        }
        Expression::Splat { value, .. } => collect_global(m, *value, consts, types),
        _ => {}
    }
}

impl Library {
    /// Read every file of [`FILES`].
    pub fn shipped() -> Result<Self, ComposeError> {
        Self::from_files(FILES)
    }

    /// Read the given files (each must be valid WGSL on its own; names must be unique).
    pub fn from_files(files: &[WgslFile]) -> Result<Self, ComposeError> {
        let mut items = Vec::new();
        let mut index: HashMap<String, usize> = HashMap::new();
        for f in files {
            for item in items_of(f)? {
                if let Some(&prev) = index.get(&item.name) {
                    let other: &Item = &items[prev];
                    return Err(ComposeError::DuplicateName {
                        name: item.name.clone(),
                        files: (other.file.to_string(), item.file.to_string()),
                    });
                }
                index.insert(item.name.clone(), items.len());
                items.push(item);
            }
        }
        Ok(Library { items, index })
    }

    /// All items, in emission order.
    pub fn items(&self) -> &[Item] {
        &self.items
    }

    /// The item called `name`.
    pub fn item(&self, name: &str) -> Option<&Item> {
        self.index.get(name).map(|&i| &self.items[i])
    }

    /// Names of every item `roots` reach, roots included.
    pub fn closure<'a>(
        &self,
        roots: impl IntoIterator<Item = &'a str>,
    ) -> Result<BTreeSet<String>, ComposeError> {
        let mut seen = BTreeSet::new();
        let mut stack: Vec<String> = Vec::new();
        for r in roots {
            if !self.index.contains_key(r) {
                return Err(ComposeError::UnknownRoot(r.to_string()));
            }
            stack.push(r.to_string());
        }
        while let Some(n) = stack.pop() {
            if !seen.insert(n.clone()) {
                continue;
            }
            if let Some(item) = self.item(&n) {
                stack.extend(item.uses.iter().filter(|u| !seen.contains(*u)).cloned());
            }
        }
        Ok(seen)
    }

    /// One WGSL module with exactly the items `roots` reach, in library order, validated by
    /// naga. Each item is preceded by its comment block; items are separated by a blank line.
    pub fn compose<'a>(
        &self,
        roots: impl IntoIterator<Item = &'a str>,
    ) -> Result<String, ComposeError> {
        let out = self.compose_text(roots)?;
        parse_and_validate(&out).map_err(|error| ComposeError::Wgsl {
            file: "<composed>".into(),
            error,
        })?;
        Ok(out)
    }

    /// The text [`Library::compose`] returns, without its naga validation: for callers that
    /// validate elsewhere or need only the bytes (the scene tests compare it with
    /// [`Scene::wgsl`](super::Scene::wgsl) for every distinct scene, and validate a sample
    /// whose argument is in `tests/scene.rs`).
    pub fn compose_text<'a>(
        &self,
        roots: impl IntoIterator<Item = &'a str>,
    ) -> Result<String, ComposeError> {
        let keep = self.closure(roots)?;
        let mut out = String::from("// Composed by prepass::scene from the shipped WGSL files.\n");
        let mut file = "";
        for item in self.items.iter().filter(|i| keep.contains(&i.name)) {
            if item.file != file {
                file = item.file;
                out.push_str(&format!("\n// ---- from wgsl/{file} ----\n"));
            }
            out.push('\n');
            out.push_str(&item.text);
            out.push('\n');
        }
        Ok(out)
    }
}
