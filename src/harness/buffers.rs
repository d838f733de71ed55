//! Bind group 0 and buffer mapping: what every run does to hand buffers to the GPU and read
//! them back.

use super::*;

/// The harness's bind group 0: uniforms at binding 0, the column buffers from binding 1 in
/// parameter order, the output buffer last (the layout `codegen` declares).
pub(crate) fn bind_group<'b>(
    device: &wgpu::Device,
    pipeline: &wgpu::ComputePipeline,
    params: &wgpu::Buffer,
    columns: impl Iterator<Item = &'b wgpu::Buffer>,
    out: &wgpu::Buffer,
    label: &str,
) -> wgpu::BindGroup {
    let mut entries = vec![wgpu::BindGroupEntry {
        binding: 0,
        resource: params.as_entire_binding(),
    }];
    for buf in columns {
        entries.push(wgpu::BindGroupEntry {
            binding: entries.len() as u32,
            resource: buf.as_entire_binding(),
        });
    }
    entries.push(wgpu::BindGroupEntry {
        binding: entries.len() as u32,
        resource: out.as_entire_binding(),
    });
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some(label),
        layout: &pipeline.get_bind_group_layout(0),
        entries: &entries,
    })
}

pub(super) fn read_back(
    gpu: &Gpu,
    staging: &wgpu::Buffer,
    bytes: u64,
) -> Result<Vec<u32>, HarnessError> {
    read_back_with(gpu, staging, bytes, <[u32]>::to_vec)
}

/// Map `slice` for `mode` and wait until it is mapped.
pub(super) fn map(
    gpu: &Gpu,
    slice: &wgpu::BufferSlice<'_>,
    mode: wgpu::MapMode,
) -> Result<(), HarnessError> {
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(mode, move |r| {
        let _ = tx.send(r);
    });
    gpu.device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| HarnessError::Readback(e.to_string()))?;
    rx.recv()
        .map_err(|e| HarnessError::Readback(e.to_string()))?
        .map_err(|e| HarnessError::Readback(e.to_string()))
}

/// `bytes` written at the start of `upload` (a `MAP_WRITE` buffer no submission in flight
/// uses), unmapped again after.
pub(super) fn write_mapped(
    gpu: &Gpu,
    upload: &wgpu::Buffer,
    bytes: &[u8],
) -> Result<(), HarnessError> {
    let slice = upload.slice(..bytes.len() as u64);
    map(gpu, &slice, wgpu::MapMode::Write)?;
    slice
        .get_mapped_range_mut()
        .map_err(|e| HarnessError::Readback(format!("{e:?}")))?
        .copy_from_slice(bytes);
    upload.unmap();
    Ok(())
}

/// The first `bytes` of `staging` (a `MAP_READ` buffer the last submission copied into), as
/// words handed to `read` while mapped; unmapped again after.
pub(super) fn read_back_with<R>(
    gpu: &Gpu,
    staging: &wgpu::Buffer,
    bytes: u64,
    read: impl FnOnce(&[u32]) -> R,
) -> Result<R, HarnessError> {
    let slice = staging.slice(..bytes);
    map(gpu, &slice, wgpu::MapMode::Read)?;
    let words = {
        let view = slice
            .get_mapped_range()
            .map_err(|e| HarnessError::Readback(format!("{e:?}")))?;
        read(bytemuck::cast_slice::<u8, u32>(&view))
    };
    staging.unmap();
    Ok(words)
}
