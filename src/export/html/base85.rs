//! Bytes as text for the page's JSON, 5 characters per 4 bytes (base64 takes 5⅓).
//!
//! The alphabet is printable ASCII without `"` and `\` (which a JSON string escapes) and
//! `<`, `>`, `&` (which the page's script data escapes): the text stands in a JSON string
//! as it is. Each group of 4 bytes, read as a big-endian number, is written as 5 digits
//! base 85, the most significant first; a last group of 1 to 3 bytes is padded with
//! zeros and written as its first 2 to 4 digits (page.js pads them with the last digit,
//! as Ascii85 does).

/// The 85 digits: `!` to `~` without `"`, `&`, `<`, `>`, `\` and the last four (`{|}~`).
pub(crate) const ALPHABET: &[u8; 85] =
    b"!#$%'()*+,-./0123456789:;=?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[]^_`abcdefghijklmnopqrstuvwxyz";

pub(crate) fn encode(bytes: &[u8]) -> String {
    let mut out = String::with_capacity(bytes.len() / 4 * 5 + 5);
    for chunk in bytes.chunks(4) {
        let mut group = [0u8; 4];
        group[..chunk.len()].copy_from_slice(chunk);
        let mut n = u32::from_be_bytes(group);
        let mut digits = [0u8; 5];
        for d in digits.iter_mut().rev() {
            *d = ALPHABET[(n % 85) as usize];
            n /= 85;
        }
        for &d in &digits[..chunk.len() + 1] {
            out.push(char::from(d));
        }
    }
    out
}

/// What page.js does: the inverse of [`encode`].
#[cfg(test)]
pub(crate) fn decode(text: &str) -> Option<Vec<u8>> {
    let digit = |c: u8| ALPHABET.iter().position(|&a| a == c).map(|d| d as u64);
    let mut out = Vec::with_capacity(text.len() / 5 * 4 + 4);
    for chunk in text.as_bytes().chunks(5) {
        if chunk.len() == 1 {
            return None;
        }
        let mut n = 0u64;
        for i in 0..5 {
            n = n * 85 + chunk.get(i).map_or(Some(84), |&c| digit(c))?;
        }
        let bytes = u32::try_from(n).ok()?.to_be_bytes();
        out.extend_from_slice(&bytes[..chunk.len() - 1]);
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_alphabet_needs_no_escape_in_the_pages_json() {
        let set: std::collections::BTreeSet<u8> = ALPHABET.iter().copied().collect();
        assert_eq!(set.len(), 85);
        for c in ALPHABET {
            assert!(c.is_ascii_graphic(), "{c}");
            assert!(!b"\"\\<>&".contains(c), "{}", char::from(*c));
        }
    }

    #[test]
    fn bytes_come_back_for_every_length() {
        let bytes: Vec<u8> = (0..=255u8).chain((0..=255u8).rev()).collect();
        for n in 0..=bytes.len().min(40) {
            let text = encode(&bytes[..n]);
            assert_eq!(
                text.len(),
                n / 4 * 5 + if n % 4 > 0 { n % 4 + 1 } else { 0 }
            );
            assert_eq!(decode(&text).as_deref(), Some(&bytes[..n]), "{n}");
        }
        assert_eq!(decode(&encode(&bytes)).unwrap(), bytes);
        assert_eq!(encode(&[0, 0, 0, 0]), "!!!!!");
        assert_eq!(encode(&[0xFF; 4]), "x:[/!");
    }
}
