//! A WGSL function's signature, read with naga.

use crate::wgsl::{WgslError, parse_and_validate};
use naga::{ScalarKind, TypeInner};

/// The 32-bit scalar types the harness moves through buffers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Scalar {
    /// `f32`
    F32,
    /// `u32`
    U32,
    /// `i32`
    I32,
}

/// A scalar or vector of a [`Scalar`]: `lanes` is 1 for a scalar, 2–4 for `vecN`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ValueType {
    /// Element type.
    pub scalar: Scalar,
    /// 1 (scalar) to 4.
    pub lanes: u8,
}

impl ValueType {
    /// 32-bit words per value.
    pub fn words(self) -> usize {
        usize::from(self.lanes)
    }

    /// WGSL spelling: `f32`, `vec3<u32>`, …
    pub fn wgsl(self) -> String {
        let s = match self.scalar {
            Scalar::F32 => "f32",
            Scalar::U32 => "u32",
            Scalar::I32 => "i32",
        };
        if self.lanes == 1 {
            s.to_string()
        } else {
            format!("vec{}<{s}>", self.lanes)
        }
    }

    /// WGSL spelling of the same shape with `u32` lanes (the bit carrier in buffers).
    pub fn wgsl_bits(self) -> String {
        ValueType {
            scalar: Scalar::U32,
            lanes: self.lanes,
        }
        .wgsl()
    }
}

impl std::fmt::Display for ValueType {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.wgsl())
    }
}

/// One parameter of a WGSL function.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Param {
    /// Name in the source.
    pub name: String,
    /// Type.
    pub ty: ValueType,
}

/// A WGSL function the harness can run: parameters and result are scalars or vectors of
/// `f32`/`u32`/`i32`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Signature {
    /// The function's name.
    pub function: String,
    /// Its parameters in order.
    pub params: Vec<Param>,
    /// Its result.
    pub result: ValueType,
}

/// Why a function's signature cannot be run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SignatureError {
    /// The source does not parse or validate.
    Wgsl(WgslError),
    /// No function of that name.
    NotFound {
        /// The name asked for.
        function: String,
        /// The functions the source does define.
        available: Vec<String>,
    },
    /// A parameter or the result is not a scalar/vector of f32, u32 or i32.
    Unsupported {
        /// The function.
        function: String,
        /// Which part: a parameter's name or `"result"`.
        part: String,
        /// naga's description of the type.
        found: String,
    },
}

impl std::fmt::Display for SignatureError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Wgsl(e) => e.fmt(f),
            Self::NotFound {
                function,
                available,
            } => write!(
                f,
                "no function `{function}` in the WGSL source (it defines: {})",
                available.join(", ")
            ),
            Self::Unsupported {
                function,
                part,
                found,
            } => write!(
                f,
                "`{function}`: {part} has type {found}; the harness runs scalars and vectors of \
                 f32, u32 and i32 (wrap other functions in one that takes and returns those)"
            ),
        }
    }
}

impl std::error::Error for SignatureError {}

impl Signature {
    /// Read the signature of `function` from `source` (which must parse and validate on its own).
    pub fn read(source: &str, function: &str) -> Result<Self, SignatureError> {
        let checked = parse_and_validate(source).map_err(SignatureError::Wgsl)?;
        Self::read_parsed(&checked.module, function)
    }

    /// [`Signature::read`] of a module already parsed and validated: a caller reading every
    /// function of a large module parses it once, not once per function.
    pub(crate) fn read_parsed(
        module: &naga::Module,
        function: &str,
    ) -> Result<Self, SignatureError> {
        let found = module
            .functions
            .iter()
            .find(|(_, f)| f.name.as_deref() == Some(function))
            .map(|(_, f)| f);
        let Some(f) = found else {
            return Err(SignatureError::NotFound {
                function: function.to_string(),
                available: module
                    .functions
                    .iter()
                    .filter_map(|(_, f)| f.name.clone())
                    .collect(),
            });
        };
        let convert = |ty: naga::Handle<naga::Type>, part: &str| {
            let inner = &module.types[ty].inner;
            let (scalar, lanes) = match inner {
                TypeInner::Scalar(s) => (*s, 1u8),
                TypeInner::Vector { size, scalar } => (*scalar, *size as u8),
                _ => (naga::Scalar::BOOL, 0),
            };
            let kind = match (scalar.kind, scalar.width) {
                (ScalarKind::Float, 4) => Some(Scalar::F32),
                (ScalarKind::Uint, 4) => Some(Scalar::U32),
                (ScalarKind::Sint, 4) => Some(Scalar::I32),
                _ => None,
            };
            match kind {
                Some(scalar) if lanes > 0 => Ok(ValueType { scalar, lanes }),
                _ => Err(SignatureError::Unsupported {
                    function: function.to_string(),
                    part: part.to_string(),
                    found: format!("{inner:?}"),
                }),
            }
        };
        let params = f
            .arguments
            .iter()
            .enumerate()
            .map(|(i, a)| {
                let name = a.name.clone().unwrap_or_else(|| format!("arg{i}"));
                Ok(Param {
                    ty: convert(a.ty, &format!("parameter `{name}`"))?,
                    name,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let result = match &f.result {
            Some(r) => convert(r.ty, "result")?,
            None => {
                return Err(SignatureError::Unsupported {
                    function: function.to_string(),
                    part: "result".into(),
                    found: "nothing (no return value)".into(),
                });
            }
        };
        Ok(Signature {
            function: function.to_string(),
            params,
            result,
        })
    }
}
