//! `projection` (Rust only): which near/far planes `Projection::new` accepts.

use super::{Func, INF, NAN, Row, SUB_MAX, V};
use prepass::projection::{DepthConvention, Projection};

/// `Projection::new` as a table value: `Ok` or the rejected field.
fn projection_new(a: &[V]) -> V {
    let conv = if a[2].bool() {
        DepthConvention::Reversed
    } else {
        DepthConvention::Standard
    };
    match Projection::new(a[0].f32(), a[1].f32(), conv) {
        Ok(_) => V::Text("Ok"),
        Err(e) if e.field == "near" => V::Text("Err(near)"),
        Err(_) => V::Text("Err(far)"),
    }
}

pub const FUNCS: &[Func] = &[Func {
    rust: "projection::Projection::new",
    wgsl: None,
    twin: projection_new,
}];

pub const WGSL_HELPERS: &[(&str, &str)] = &[];

#[rustfmt::skip]
pub const ROWS: &[Row] = &[
    Row { func: "projection::Projection::new", case: "NaN near", args: &[V::F32(NAN), V::F32(1.0), V::Bool(false)], expect: V::Text("Err(near)"), why: "names the field" },
    Row { func: "projection::Projection::new", case: "zero near", args: &[V::F32(0.0), V::F32(1.0), V::Bool(true)], expect: V::Text("Err(near)"), why: "near must be > 0" },
    Row { func: "projection::Projection::new", case: "subnormal near", args: &[V::F32(SUB_MAX), V::F32(1.0), V::Bool(false)], expect: V::Text("Err(near)"), why: "near must be a normal float" },
    Row { func: "projection::Projection::new", case: "+Inf near", args: &[V::F32(INF), V::F32(INF), V::Bool(false)], expect: V::Text("Err(near)"), why: "near must be finite" },
    Row { func: "projection::Projection::new", case: "NaN far", args: &[V::F32(1.0), V::F32(NAN), V::Bool(false)], expect: V::Text("Err(far)"), why: "names the field" },
    Row { func: "projection::Projection::new", case: "far ≤ near", args: &[V::F32(1.0), V::F32(1.0), V::Bool(false)], expect: V::Text("Err(far)"), why: "far must exceed near" },
    Row { func: "projection::Projection::new", case: "out of range: near·(2^24 − 1) overflows", args: &[V::F32(1e32), V::F32(INF), V::Bool(false)], expect: V::Text("Err(near)"), why: "the 24-bit path would overflow" },
    Row { func: "projection::Projection::new", case: "out of range: far/near > 2^126", args: &[V::F32(1e-4), V::F32(1e36), V::Bool(false)], expect: V::Text("Err(far)"), why: "n/f would be subnormal: use +Inf" },
    Row { func: "projection::Projection::new", case: "+Inf far", args: &[V::F32(0.1), V::F32(INF), V::Bool(true)], expect: V::Text("Ok"), why: "infinite projection" },
];
