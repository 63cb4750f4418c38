//! Pictures out: PNG bytes for an [`Outputs`](csgpix_output::Outputs) stage.

use std::io::Write;

/// Encode `img` as PNG into `w`.
pub fn write_png(w: &mut dyn Write, img: &image::RgbImage) -> std::io::Result<()> {
    let mut buf = std::io::Cursor::new(Vec::new());
    img.write_to(&mut buf, image::ImageFormat::Png)
        .map_err(std::io::Error::other)?;
    w.write_all(buf.get_ref())
}

/// Encode an 8-bit indexed PNG of `width` × `height` into `w`: each pixel is its byte of
/// `indices` (a voxel's label code or grey value, kept as it is), shown through `palette`
/// (an RGB entry per index up to the largest used). A viewer shows the colours; a reader of
/// the indices gets the codes.
pub fn write_indexed_png(
    w: &mut dyn Write,
    (width, height): (u32, u32),
    indices: &[u8],
    palette: &[[u8; 3]],
) -> std::io::Result<()> {
    let mut enc = png::Encoder::new(w, width, height);
    enc.set_color(png::ColorType::Indexed);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_palette(palette.as_flattened().to_vec());
    let mut writer = enc.write_header().map_err(std::io::Error::other)?;
    writer
        .write_image_data(indices)
        .map_err(std::io::Error::other)?;
    writer.finish().map_err(std::io::Error::other)
}
