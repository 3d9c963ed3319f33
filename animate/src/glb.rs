//! The binary glTF container: a 12-byte header, a JSON chunk and a binary chunk.
//!
//! glTF 2.0 §4.4: the header is the magic `glTF`, the version 2 and the file's length, all
//! little-endian u32; each chunk is its length, its type (`JSON`, `BIN\0`) and its bytes, padded
//! to a multiple of 4 (the JSON with spaces, the binary with zeros).

use crate::error::AnimateError;

/// `glTF` read as a little-endian u32.
pub const MAGIC: u32 = 0x4654_6C67;
/// The JSON chunk's type, `JSON`.
pub const JSON_CHUNK: u32 = 0x4E4F_534A;
/// The binary chunk's type, `BIN\0`.
pub const BIN_CHUNK: u32 = 0x004E_4942;

/// The two chunks of a `.glb` file, borrowed from its bytes (their padding included).
#[derive(Debug, Clone, Copy)]
pub struct Glb<'a> {
    /// The JSON chunk.
    pub json: &'a [u8],
    /// The binary chunk (empty if the file has none).
    pub bin: &'a [u8],
}

/// `bytes` padded with `fill` to a multiple of 4.
fn padded(bytes: &[u8], fill: u8) -> Vec<u8> {
    let mut v = bytes.to_vec();
    v.resize(bytes.len().next_multiple_of(4), fill);
    v
}

/// The `.glb` of a JSON document and its binary buffer.
///
/// # Errors
/// [`AnimateError::TooLarge`] past the format's u32 lengths.
pub fn write(json: &[u8], bin: &[u8]) -> Result<Vec<u8>, AnimateError> {
    let (json, bin) = (padded(json, b' '), padded(bin, 0));
    let total = 12 + 8 + json.len() + if bin.is_empty() { 0 } else { 8 + bin.len() };
    let length = u32::try_from(total).map_err(|_| AnimateError::TooLarge {
        bytes: total as u64,
    })?;
    let mut out = Vec::with_capacity(total);
    for word in [MAGIC, 2, length] {
        out.extend_from_slice(&word.to_le_bytes());
    }
    // Each chunk's length fits: both are shorter than the total, which fits.
    for (kind, chunk) in [(JSON_CHUNK, &json), (BIN_CHUNK, &bin)] {
        if chunk.is_empty() && kind == BIN_CHUNK {
            continue;
        }
        out.extend_from_slice(&(chunk.len() as u32).to_le_bytes());
        out.extend_from_slice(&kind.to_le_bytes());
        out.extend_from_slice(chunk);
    }
    Ok(out)
}

/// The chunks of a `.glb`, checked: the magic, version 2, the header's length equal to the
/// file's, each chunk inside the file and a multiple of 4 long, the JSON chunk first.
///
/// # Errors
/// [`AnimateError::BadGlb`] naming the first rule broken and where.
///
/// # Examples
/// ```
/// let glb = precess::animate::glb::write(br#"{"asset":{"version":"2.0"}}"#, &[1, 2, 3])?;
/// let read = precess::animate::glb::parse(&glb)?;
/// assert_eq!(read.json.len() % 4, 0);
/// assert_eq!(read.bin, &[1, 2, 3, 0]);
/// # Ok::<(), precess::animate::AnimateError>(())
/// ```
pub fn parse(bytes: &[u8]) -> Result<Glb<'_>, AnimateError> {
    let bad = |why, at| AnimateError::BadGlb { why, at };
    let word = |at: usize| -> Result<u32, AnimateError> {
        let b = bytes
            .get(at..at + 4)
            .ok_or(bad("the file ends early", at))?;
        Ok(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    if word(0)? != MAGIC {
        return Err(bad("no glTF magic", 0));
    }
    if word(4)? != 2 {
        return Err(bad("the version is not 2", 4));
    }
    if word(8)? as usize != bytes.len() {
        return Err(bad("the header's length is not the file's", 8));
    }
    let mut chunks = Vec::new();
    let mut at = 12;
    while at < bytes.len() {
        let len = word(at)? as usize;
        let kind = word(at + 4)?;
        let body = bytes
            .get(at + 8..at + 8 + len)
            .ok_or(bad("a chunk runs past the end", at))?;
        if !len.is_multiple_of(4) {
            return Err(bad("a chunk's length is not a multiple of 4", at));
        }
        chunks.push((kind, body));
        at += 8 + len;
    }
    match chunks.as_slice() {
        [(JSON_CHUNK, json)] => Ok(Glb { json, bin: &[] }),
        [(JSON_CHUNK, json), (BIN_CHUNK, bin), ..] => Ok(Glb { json, bin }),
        _ => Err(bad(
            "the first chunk is not JSON, or the second not BIN",
            12,
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chunks_are_padded_and_read_back() {
        let glb = write(b"{}", &[7; 5]).unwrap();
        // 12 + (8 + 4) + (8 + 8).
        assert_eq!(glb.len(), 40);
        assert_eq!(&glb[0..4], b"glTF");
        let read = parse(&glb).unwrap();
        assert_eq!(read.json, b"{}  ");
        assert_eq!(read.bin, &[7, 7, 7, 7, 7, 0, 0, 0]);
    }

    #[test]
    fn broken_files_are_refused_with_the_place() {
        let glb = write(b"{}", &[1]).unwrap();
        let mut short = glb.clone();
        short.pop();
        assert!(matches!(
            parse(&short),
            Err(AnimateError::BadGlb { at: 8, .. })
        ));
        let mut magic = glb.clone();
        magic[0] = b'x';
        assert!(matches!(
            parse(&magic),
            Err(AnimateError::BadGlb { at: 0, .. })
        ));
        let mut long_chunk = glb.clone();
        long_chunk[12] = 200;
        assert!(matches!(
            parse(&long_chunk),
            Err(AnimateError::BadGlb { at: 12, .. })
        ));
    }
}
