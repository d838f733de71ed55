//! The values a precision check moves through the harness's buffers: [`WgslValue`] (one WGSL
//! parameter or result, as its bits) and [`WgslArgs`] (the arguments of one call). Re-exported
//! from [`check`](super::check), where they are used.

use crate::harness::{Scalar, ValueType};
use glam::{IVec2, IVec3, IVec4, UVec2, UVec3, UVec4, Vec2, Vec3, Vec4};
use std::fmt::Debug;

/// A value that crosses the harness's buffers as one WGSL parameter or result: a scalar or
/// vector of `f32`, `u32` or `i32`, moved as its bits (NaN payloads and signed zeros intact).
pub trait WgslValue: Clone + Debug {
    /// Its WGSL type.
    const TYPE: ValueType;
    /// Append its lanes' bits.
    fn push_words(&self, out: &mut Vec<u32>);
    /// Read it back from `TYPE.words()` words.
    fn from_words(words: &[u32]) -> Self;
}

const fn vt(scalar: Scalar, lanes: u8) -> ValueType {
    ValueType { scalar, lanes }
}

macro_rules! scalar_value {
    ($t:ty, $s:expr, $to:expr, $from:expr) => {
        impl WgslValue for $t {
            const TYPE: ValueType = vt($s, 1);
            fn push_words(&self, out: &mut Vec<u32>) {
                out.push($to(*self));
            }
            fn from_words(w: &[u32]) -> Self {
                $from(w[0])
            }
        }
    };
}
scalar_value!(f32, Scalar::F32, f32::to_bits, f32::from_bits);
scalar_value!(u32, Scalar::U32, |x| x, |w| w);
scalar_value!(i32, Scalar::I32, |x: i32| x as u32, |w: u32| w as i32);

macro_rules! array_value {
    ($($n:literal),*) => {$(
        impl<T: WgslValue + Copy> WgslValue for [T; $n] {
            const TYPE: ValueType = {
                assert!(T::TYPE.lanes == 1, "arrays of scalars only");
                vt(T::TYPE.scalar, $n)
            };
            fn push_words(&self, out: &mut Vec<u32>) {
                for x in self {
                    x.push_words(out);
                }
            }
            fn from_words(w: &[u32]) -> Self {
                std::array::from_fn(|i| T::from_words(&w[i..i + 1]))
            }
        }
    )*};
}
array_value!(2, 3, 4);

macro_rules! glam_value {
    ($($t:ty => $a:ty),*) => {$(
        impl WgslValue for $t {
            const TYPE: ValueType = <$a as WgslValue>::TYPE;
            fn push_words(&self, out: &mut Vec<u32>) {
                <$a>::from(*self).push_words(out);
            }
            fn from_words(w: &[u32]) -> Self {
                <$t>::from(<$a>::from_words(w))
            }
        }
    )*};
}
glam_value!(
    Vec2 => [f32; 2], Vec3 => [f32; 3], Vec4 => [f32; 4],
    UVec2 => [u32; 2], UVec3 => [u32; 3], UVec4 => [u32; 4],
    IVec2 => [i32; 2], IVec3 => [i32; 3], IVec4 => [i32; 4]
);

/// The arguments of one call: a single [`WgslValue`] for a one-parameter function, a tuple of
/// them (up to four) for more. Implement it for your own input struct to feed a strategy that
/// produces one.
pub trait WgslArgs: Clone + Debug {
    /// The WGSL type of each parameter, in order.
    fn param_types() -> Vec<ValueType>;
    /// Append parameter `k`'s bits to `columns[k]`, for every `k`.
    fn push_columns(&self, columns: &mut [Vec<u32>]);
}

impl<T: WgslValue> WgslArgs for T {
    fn param_types() -> Vec<ValueType> {
        vec![T::TYPE]
    }
    fn push_columns(&self, columns: &mut [Vec<u32>]) {
        self.push_words(&mut columns[0]);
    }
}

macro_rules! tuple_args {
    ($(($($t:ident $i:tt),*)),*) => {$(
        impl<$($t: WgslValue),*> WgslArgs for ($($t,)*) {
            fn param_types() -> Vec<ValueType> {
                vec![$($t::TYPE),*]
            }
            fn push_columns(&self, columns: &mut [Vec<u32>]) {
                $(self.$i.push_words(&mut columns[$i]);)*
            }
        }
    )*};
}
tuple_args!((A 0), (A 0, B 1), (A 0, B 1, C 2), (A 0, B 1, C 2, D 3));

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_round_trip_their_bits() {
        let mut w = Vec::new();
        (-0.0f32).push_words(&mut w);
        Vec3::new(1.0, f32::NAN, -2.0).push_words(&mut w);
        (-5i32).push_words(&mut w);
        assert_eq!(w[0], 0x8000_0000);
        assert_eq!(f32::from_words(&w[0..1]).to_bits(), 0x8000_0000);
        assert!(Vec3::from_words(&w[1..4]).y.is_nan());
        assert_eq!(i32::from_words(&w[4..5]), -5);
        assert_eq!(<(u32, Vec3)>::param_types(), vec![u32::TYPE, Vec3::TYPE]);
    }
}
