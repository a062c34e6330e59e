//! Reading the image a user compares with the exact render: a file or bytes of any size, TGA,
//! PNG or what else the `image` crate reads (by the name's extension unless the bytes say
//! otherwise), as an 8-bit RGB picture. Errors are messages for the viewer's status bar.

use std::path::Path;

use image::RgbImage;

/// Reads an image file to compare (any size; TGA, PNG and what else the `image` crate reads).
pub fn read_their_image(path: &Path) -> Result<RgbImage, String> {
    let bytes = std::fs::read(path)
        .map_err(|error| format!("cannot read '{}': {error}", path.display()))?;
    decode_their_image(path, &bytes)
}

/// Decodes the image `bytes` named `name` (the format by the name's extension, as for a file,
/// unless the bytes say otherwise), as an 8-bit RGB picture.
pub fn decode_their_image(name: &Path, bytes: &[u8]) -> Result<RgbImage, String> {
    let mut reader = image::ImageReader::new(std::io::Cursor::new(bytes));
    if let Ok(format) = image::ImageFormat::from_path(name) {
        reader.set_format(format);
    }
    let image = reader
        .with_guessed_format()
        .map_err(|error| format!("cannot read '{}': {error}", name.display()))?
        .decode()
        .map_err(|error| format!("cannot read the image '{}': {error}", name.display()))?;
    Ok(image.to_rgb8())
}
