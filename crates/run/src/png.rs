//! Pictures out: PNG bytes for an [`Outputs`](crate::output::Outputs) stage.

use std::io::Write;

/// Encode `img` as PNG into `w`.
pub fn write_png(w: &mut dyn Write, img: &image::RgbImage) -> std::io::Result<()> {
    let mut buf = std::io::Cursor::new(Vec::new());
    img.write_to(&mut buf, image::ImageFormat::Png)
        .map_err(std::io::Error::other)?;
    w.write_all(buf.get_ref())
}
