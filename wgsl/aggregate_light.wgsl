// prepass — God of War III's aggregate vertex lights (Vassily Filippov, "Dynamic lighting in
// GOW3", Sony Santa Monica; Advances in Real-Time Rendering in 3D Graphics and Games, SIGGRAPH
// 2011): per vertex, many lights are folded into one aggregate light whose position is
// interpolated per pixel.
// Rust twin: src/lighting/aggregate_light.rs. Tests: tests/aggregate_light.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Per vertex V, for each light i with position P_i and weight W_i (its intensity at V):
//   acc.xyz = Σ W_i·L_i with L_i = (P_i − V)/|P_i − V|,   acc.w = Σ W_i/|P_i − V|
//   aggregate position  P_agg = V + acc.xyz / acc.w         (Filippov's "back to positions")
//   aggregate direction L_agg = acc.xyz / |acc.xyz|
//   aggregate colour    C_agg = Σ C_i (L_i · L_agg)
// Per pixel: C_agg · max(N · normalize(P_agg − p), 0) with P_agg interpolated.
// For scalar luminances l_i with every N·L_i >= 0 this is exact: (N·L_agg)·l_agg =
// N·(Σ l_i L_i) = Σ l_i (N·L_i), because l_agg = Σ l_i (L_i·L_agg) = |Σ l_i L_i|.
//
// Bad input (same on both sides): a light with any NaN/Inf input, or closer to the vertex than
// 2^-64 in every coordinate (its direction is undefined), is skipped (acc unchanged); weights
// and colours are clamped to [0, 2^40] (negative intensities add nothing). When the
// weighted directions cancel (largest component of acc.xyz zero or subnormal) the direction is
// zero, so every colour term is zero, and the position is the vertex itself; per pixel, a zero-length
// P_agg − p, a bad normal or non-finite input gives 0. Every result is finite (WGSL leaves a
// run-time ±Inf indeterminate): accumulator, colour and position lanes are read finite first
// (NaN → 0, ±Inf and beyond ±2^100 → ±2^100; a skipped light returns the accumulator so read),
// the aggregate direction's within ±2^40, so no difference, sum or product overflows; an
// aggregate position whose offset acc.xyz/acc.w would reach 2^101 is the vertex.

const AGGREGATE_LIGHT_WEIGHT_MAX = 1099511627776.0; // 2^40
// The largest magnitude of a position or accumulator lane the functions compute with (2^100):
// differences and sums of such lanes cannot overflow.
const AGGREGATE_LIGHT_LIMIT = 1.2676506e30;

// True when no component of v is NaN or ±Inf (judged from the bits).
fn aggregate_light_finite3(v: vec3<f32>) -> bool {
    return all((bitcast<vec3<u32>>(v) & vec3<u32>(0x7fffffffu)) < vec3<u32>(0x7f800000u));
}

// v with every lane made finite and within ±limit, from its bits: NaN → 0, ±inf → ±limit. Sums
// and products of such lanes stay finite (WGSL leaves a run-time ±inf indeterminate).
fn aggregate_light_sane3(v: vec3<f32>, limit: f32) -> vec3<f32> {
    let bits = bitcast<vec3<u32>>(v);
    let mag = bits & vec3<u32>(0x7fffffffu);
    let big = select(vec3<f32>(limit), vec3<f32>(-limit), (bits & vec3<u32>(0x80000000u)) != vec3<u32>(0u));
    let finite = clamp(select(v, vec3<f32>(0.0), mag >= vec3<u32>(0x7f800000u)), vec3<f32>(-limit),
        vec3<f32>(limit));
    return select(finite, big, mag == vec3<u32>(0x7f800000u));
}

// aggregate_light_sane3 on all four lanes of an accumulator.
fn aggregate_light_sane4(v: vec4<f32>, limit: f32) -> vec4<f32> {
    let w = aggregate_light_sane3(vec3<f32>(v.w, 0.0, 0.0), limit).x;
    return vec4<f32>(aggregate_light_sane3(v.xyz, limit), w);
}

// v/|v| scaled by its largest component first (no overflow), or zero when v is non-finite or
// its largest component is below `smallest` (bit pattern of a positive f32).
// The power of two that scales a normal m >= 0 into [1, 4): exact, where v / m would divide by
// a number WGSL's / need not handle (beyond 2^126).
fn aggregate_light_scale(m: f32) -> f32 {
    return bitcast<f32>(max(254u - ((bitcast<u32>(m) >> 23u) & 0xffu), 1u) << 23u);
}

fn aggregate_light_unit(v: vec3<f32>, smallest: u32) -> vec3<f32> {
    // The bits are judged before abs and max see a NaN or an infinity.
    if (!aggregate_light_finite3(v)) {
        return vec3<f32>(0.0);
    }
    let a = abs(v);
    let m = max(a.x, max(a.y, a.z));
    if (bitcast<u32>(m) < smallest) {
        return vec3<f32>(0.0);
    }
    let s = v * aggregate_light_scale(m);
    return s * inverseSqrt(dot(s, s));
}

// Fold light i into a vertex's accumulator (start from vec4(0)).
fn aggregate_light_accumulate(acc: vec4<f32>, vertex: vec3<f32>, light_position: vec3<f32>,
                              weight: f32) -> vec4<f32> {
    let a0 = aggregate_light_sane4(acc, AGGREGATE_LIGHT_LIMIT);
    let w_bits = bitcast<u32>(weight) & 0x7fffffffu;
    if (!aggregate_light_finite3(vertex) || !aggregate_light_finite3(light_position)
        || w_bits >= 0x7f800000u) {
        return a0;
    }
    let rel = aggregate_light_sane3(light_position, AGGREGATE_LIGHT_LIMIT)
        - aggregate_light_sane3(vertex, AGGREGATE_LIGHT_LIMIT);
    let a = abs(rel);
    let m = max(a.x, max(a.y, a.z));
    // 0x1f800000 = 2^-64
    if (bitcast<u32>(m) < 0x1f800000u) {
        return a0;
    }
    let w = clamp(weight, 0.0, AGGREGATE_LIGHT_WEIGHT_MAX);
    let sc = aggregate_light_scale(m);
    let s = rel * sc;
    let inv = inverseSqrt(dot(s, s));
    // |rel| = 1/(inv·sc), so W/|rel| = W·inv·sc (m >= 2^-64, so sc <= 2^64: no overflow).
    return a0 + vec4<f32>(w * (s * inv), w * inv * sc);
}

fn aggregate_light_direction(acc: vec4<f32>) -> vec3<f32> {
    return aggregate_light_unit(acc.xyz, 0x00800000u);
}

// The aggregate light's position V + acc.xyz/acc.w (the vertex when nothing was accumulated or
// the directions cancel).
fn aggregate_light_position(acc: vec4<f32>, vertex: vec3<f32>) -> vec3<f32> {
    let v = aggregate_light_sane3(vertex, AGGREGATE_LIGHT_LIMIT);
    // The bits are judged before abs, max and the comparisons see a NaN or an infinity.
    if (!aggregate_light_finite3(acc.xyz) || !((bitcast<u32>(acc.w) & 0x7fffffffu) < 0x7f800000u)) {
        return v;
    }
    let a = abs(acc.xyz);
    let m = max(a.x, max(a.y, a.z));
    // m/W below 2^101, from the exponents, so the quotient and the sum stay finite.
    if (bitcast<u32>(m) < 0x00800000u || !(acc.w >= 1.1754944e-38)
        || i32(bitcast<u32>(m)) - i32(bitcast<u32>(acc.w)) >= 838860800) {
        return v;
    }
    // WGSL's / is specified for divisors in [2^-126, 2^126]: a larger W is scaled by 2^-64 first.
    let big = acc.w > 8.507059e37;
    let x = select(acc.xyz, acc.xyz * 5.421011e-20, big);
    return v + x / select(acc.w, acc.w * 5.421011e-20, big);
}

fn aggregate_light_accumulate_colour(colour_acc: vec3<f32>, vertex: vec3<f32>,
                                     light_position: vec3<f32>, colour: vec3<f32>,
                                     aggregate_direction: vec3<f32>) -> vec3<f32> {
    let c0 = aggregate_light_sane3(colour_acc, AGGREGATE_LIGHT_LIMIT);
    if (!aggregate_light_finite3(vertex) || !aggregate_light_finite3(light_position)
        || !aggregate_light_finite3(colour) || !aggregate_light_finite3(aggregate_direction)) {
        return c0;
    }
    let rel = aggregate_light_sane3(light_position, AGGREGATE_LIGHT_LIMIT)
        - aggregate_light_sane3(vertex, AGGREGATE_LIGHT_LIMIT);
    let a = abs(rel);
    let m = max(a.x, max(a.y, a.z));
    if (bitcast<u32>(m) < 0x1f800000u) {
        return c0;
    }
    let l = aggregate_light_unit(rel, 0x1f800000u);
    let c = clamp(colour, vec3<f32>(0.0), vec3<f32>(AGGREGATE_LIGHT_WEIGHT_MAX));
    let d = aggregate_light_sane3(aggregate_direction, AGGREGATE_LIGHT_WEIGHT_MAX);
    return c0 + c * dot(l, d);
}

fn aggregate_light_diffuse(normal: vec3<f32>, position: vec3<f32>, aggregate_position: vec3<f32>,
                           aggregate_colour: vec3<f32>) -> vec3<f32> {
    if (!aggregate_light_finite3(position) || !aggregate_light_finite3(aggregate_position)
        || !aggregate_light_finite3(aggregate_colour)) {
        return vec3<f32>(0.0);
    }
    let n = aggregate_light_unit(normal, 0x00800000u);
    let l = aggregate_light_unit(aggregate_light_sane3(aggregate_position, AGGREGATE_LIGHT_LIMIT)
        - aggregate_light_sane3(position, AGGREGATE_LIGHT_LIMIT), 0x00800000u);
    let c = aggregate_light_sane3(aggregate_colour, AGGREGATE_LIGHT_LIMIT);
    return max(c * max(dot(n, l), 0.0), vec3<f32>(0.0));
}
