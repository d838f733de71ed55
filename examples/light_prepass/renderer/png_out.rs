//! PNG output through the `png` crate (a well-kept pure-Rust encoder; `image` would bring
//! decoders this example never uses).

use std::path::Path;

/// Write 8-bit RGB pixels (row-major from the top) as a PNG.
pub fn write_rgb(path: &Path, width: u32, height: u32, rgb: &[[u8; 3]]) -> Result<(), String> {
    let file = std::fs::File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), width, height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Best);
    let mut w = enc
        .write_header()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    w.write_image_data(rgb.as_flattened())
        .map_err(|e| format!("{}: {e}", path.display()))
}
