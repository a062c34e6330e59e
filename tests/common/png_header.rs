//! PNG files built by hand: a header that announces any size, over any bytes (for images that
//! announce more than they hold, such as decompression bombs).
#![allow(dead_code)] // each test file uses its own share

/// The CRC-32 of PNG chunks (ISO 3309, bit by bit).
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = 0xFFFF_FFFF_u32;
    for &byte in bytes {
        crc ^= u32::from(byte);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

/// A PNG of `width`×`height` 8-bit RGB pixels whose data is one IDAT chunk of `data` (a zlib
/// stream, or anything).
pub(crate) fn png(width: u32, height: u32, data: &[u8]) -> Vec<u8> {
    let mut bytes = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut chunk = |kind: &[u8; 4], body: &[u8]| {
        bytes.extend_from_slice(&(body.len() as u32).to_be_bytes());
        let mut typed = kind.to_vec();
        typed.extend_from_slice(body);
        bytes.extend_from_slice(&typed);
        bytes.extend_from_slice(&crc32(&typed).to_be_bytes());
    };
    let mut header = width.to_be_bytes().to_vec();
    header.extend_from_slice(&height.to_be_bytes());
    header.extend_from_slice(&[8, 2, 0, 0, 0]);
    chunk(b"IHDR", &header);
    chunk(b"IDAT", data);
    chunk(b"IEND", &[]);
    bytes
}

/// A zlib stream of `length` zero bytes (at least 1) in as few bytes as a fixed-Huffman deflate
/// block allows: a literal zero, then matches of 258 bytes at distance 1 (13 bits each), so
/// that a few megabytes inflate to hundreds.
pub(crate) fn zlib_of_zeros(length: u64) -> Vec<u8> {
    let mut bytes = vec![0x78, 0x01];
    let (mut bits, mut count) = (0_u64, 0_u32);
    let mut put = |value: u64, width: u32, bytes: &mut Vec<u8>| {
        bits |= value << count;
        count += width;
        while count >= 8 {
            bytes.push(bits as u8);
            bits >>= 8;
            count -= 8;
        }
    };
    // A code of the fixed table, most significant bit first.
    let code = |value: u64, width: u32| -> u64 {
        (0..width).fold(0, |reversed, i| (reversed << 1) | ((value >> i) & 1))
    };
    put(0b011, 3, &mut bytes); // the last block, fixed codes
    put(code(0x30, 8), 8, &mut bytes); // literal 0
    let mut left = length - 1;
    while left >= 258 {
        put(code(0b1100_0101, 8), 8, &mut bytes); // length 258
        put(0, 5, &mut bytes); // distance 1
        left -= 258;
    }
    for _ in 0..left {
        put(code(0x30, 8), 8, &mut bytes);
    }
    put(0, 7, &mut bytes); // end of block
    put(0, 7, &mut bytes); // to a whole byte
    let adler = ((length % 65_521) << 16) | 1;
    bytes.extend_from_slice(&(adler as u32).to_be_bytes());
    bytes
}

/// A PNG of `width`×`height` black 8-bit RGB pixels with a colour profile (`iCCP`) of
/// `profile_bytes` zero bytes (compressed as [`zlib_of_zeros`]).
pub(crate) fn black_png_with_profile(width: u32, height: u32, profile_bytes: u64) -> Vec<u8> {
    let rows = zlib_of_zeros(u64::from(height) * (1 + 3 * u64::from(width)));
    let plain = png(width, height, &rows);
    let mut profile = b"bomb\0\0".to_vec();
    profile.extend_from_slice(&zlib_of_zeros(profile_bytes));
    let mut chunk = (profile.len() as u32).to_be_bytes().to_vec();
    let mut typed = b"iCCP".to_vec();
    typed.extend_from_slice(&profile);
    chunk.extend_from_slice(&typed);
    chunk.extend_from_slice(&crc32(&typed).to_be_bytes());
    // After the signature and IHDR (8 + 25 bytes).
    [&plain[..33], &chunk[..], &plain[33..]].concat()
}
