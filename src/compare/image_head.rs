//! What an image file's first bytes announce, read before the rest: whether it is an image at
//! all (a device, an endless stream or a file of garbage is refused by its first bytes, never
//! read to the file limit), and for an uncompressed or run-length TGA the most bytes it can
//! need. And a PNG's chunks that say nothing of its pixels (a colour profile, text), left out
//! before it is decoded: a 1 MB `iCCP` chunk can inflate to a gigabyte.

/// How many bytes [`announced_length`] needs: a TGA header (the longest of the signatures).
pub(super) const HEAD_BYTES: usize = 18;

/// Room for a TGA's trailing areas (its developer and extension areas and footer) and slack.
const TGA_TRAILER_BYTES: u64 = 64 << 10;

/// What `head` (the first [`HEAD_BYTES`] of a file, fewer where it is shorter) announces: an
/// image of a format the decoder knows by its signature (`Ok(None)`: its length unknown), a TGA
/// with the most bytes it can need (`Ok(Some(bytes))`), or not an image (`Err`, why).
pub(super) fn announced_length(head: &[u8]) -> Result<Option<u64>, String> {
    if image::guess_format(head).is_ok() {
        return Ok(None);
    }
    tga_length(head).map(Some).ok_or_else(|| {
        "its first bytes are not those of an image (TGA, PNG or another format this program \
         reads): not read further"
            .to_owned()
    })
}

/// The most bytes the TGA whose header is `head` can need, where `head` is a TGA header a
/// picture can have: a colour-mapped, true-colour or grey image, uncompressed or run-length, of
/// a size and depth that exist.
fn tga_length(head: &[u8]) -> Option<u64> {
    let head: &[u8; HEAD_BYTES] = head.get(..HEAD_BYTES)?.try_into().ok()?;
    let id_bytes = u64::from(head[0]);
    let map_type = head[1];
    let image_type = head[2];
    let map_entries = u64::from(u16::from_le_bytes([head[5], head[6]]));
    let map_entry_bits = u64::from(head[7]);
    let width = u64::from(u16::from_le_bytes([head[12], head[13]]));
    let height = u64::from(u16::from_le_bytes([head[14], head[15]]));
    let depth_bits = head[16];
    if map_type > 1
        || ![1, 2, 3, 9, 10, 11].contains(&image_type)
        || ![8, 15, 16, 24, 32].contains(&depth_bits)
        || width == 0
        || height == 0
    {
        return None;
    }
    let pixel_bytes = u64::from(depth_bits).div_ceil(8);
    let map_bytes = if map_type == 1 {
        map_entries * map_entry_bits.div_ceil(8)
    } else {
        0
    };
    // Run-length: at worst a packet of one pixel each, its count byte before it.
    let per_pixel = if image_type >= 9 {
        pixel_bytes + 1
    } else {
        pixel_bytes
    };
    Some(HEAD_BYTES as u64 + id_bytes + map_bytes + width * height * per_pixel + TGA_TRAILER_BYTES)
}

/// `bytes`, a PNG, with only the chunks that make its pixels (the critical ones and `tRNS`);
/// `None` where there is nothing to leave out, or `bytes` is not a PNG (the decoder says why).
pub(super) fn png_pixels_only(bytes: &[u8]) -> Option<Vec<u8>> {
    const SIGNATURE: &[u8; 8] = b"\x89PNG\r\n\x1a\n";
    if !bytes.starts_with(SIGNATURE) {
        return None;
    }
    let mut kept: Vec<(usize, usize)> = vec![(0, SIGNATURE.len())];
    let mut dropped = false;
    let mut at = SIGNATURE.len();
    while let Some(header) = bytes.get(at..at + 8) {
        let length = u32::from_be_bytes([header[0], header[1], header[2], header[3]]) as usize;
        let end = at.saturating_add(12).saturating_add(length);
        if end > bytes.len() {
            // A chunk cut short: kept as it is, for the decoder to say so.
            break;
        }
        let kind = &header[4..8];
        // An ancillary chunk's first letter is lower case.
        if kind[0].is_ascii_uppercase() || kind == b"tRNS" {
            kept.push((at, end));
        } else {
            dropped = true;
        }
        at = end;
    }
    if !dropped {
        return None;
    }
    kept.push((at, bytes.len()));
    let mut pixels_only = Vec::with_capacity(kept.iter().map(|(a, b)| b - a).sum());
    for (start, end) in kept {
        pixels_only.extend_from_slice(&bytes[start..end]);
    }
    Some(pixels_only)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_course_tga_header_is_an_image_and_zeros_or_text_are_not() {
        // 200×200, uncompressed true colour, 24 bits (what the course's code writes).
        let mut tga = [0_u8; HEAD_BYTES];
        tga[2] = 2;
        tga[12..14].copy_from_slice(&200_u16.to_le_bytes());
        tga[14..16].copy_from_slice(&200_u16.to_le_bytes());
        tga[16] = 24;
        assert_eq!(
            announced_length(&tga),
            Ok(Some(18 + 200 * 200 * 3 + TGA_TRAILER_BYTES))
        );
        assert!(announced_length(&[0; HEAD_BYTES]).is_err());
        assert!(announced_length(b"hello, this is not").is_err());
        assert_eq!(announced_length(b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR"), Ok(None));
    }
}
