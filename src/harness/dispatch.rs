//! [`Dispatch`]: one dispatch of a kernel, self-contained, for another WebGPU implementation.

use super::*;

/// One dispatch of a [`Kernel`], self-contained, for a WebGPU implementation other than wgpu
/// (see [`Kernel::dispatch`]). Bind group 0: binding 0 the uniform buffer (`uniform`), bindings
/// 1… the storage buffers of `columns` in order, the last binding the output buffer of
/// `count × result.words()` words; dispatch `groups[0] × groups[1]` workgroups of
/// [`WORKGROUP_SIZE`] on entry point `entry`.
#[derive(Clone, Debug)]
pub struct Dispatch {
    /// The function's source with the generated entry point appended.
    pub source: String,
    /// The entry point's name.
    pub entry: &'static str,
    /// The uniform buffer's words.
    pub uniform: Vec<u32>,
    /// Each column's bytes, in binding order.
    pub columns: Vec<Vec<u8>>,
    /// Workgroups in x and y.
    pub groups: [u32; 2],
    /// Elements.
    pub count: u64,
    /// Type of each result.
    pub result: ValueType,
}

impl Dispatch {
    /// Words the output buffer holds.
    pub fn output_words(&self) -> usize {
        self.count as usize * self.result.words()
    }

    /// The results another implementation read back, as the harness's [`Output`]; an error
    /// unless there are exactly [`Dispatch::output_words`] of them.
    pub fn output(&self, words: Vec<u32>) -> Result<Output, HarnessError> {
        if words.len() != self.output_words() {
            return Err(HarnessError::Readback(format!(
                "{} words read back, {} expected",
                words.len(),
                self.output_words()
            )));
        }
        Ok(Output {
            ty: self.result,
            words,
        })
    }
}
