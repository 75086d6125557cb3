//! Numbers as measurement files write them.

/// Parses a number as written in measurement files: `.` or (with `decimal_comma`) `,`
/// as decimal mark, a Unicode minus accepted; rejects NaN and infinities. The text is
/// parsed as it is first, and copied only when that fails (nearly every number is plain).
pub fn parse_number(text: &str, decimal_comma: bool) -> Result<f64, NumberError> {
    if let Some(x) = plain_decimal(text.trim_ascii()) {
        return Ok(x);
    }
    let t = text.trim();
    // Rust accepts `inf`, `nan` and `infinity`; a measurement never holds them.
    let value: f64 = match t.parse() {
        Ok(x) => x,
        Err(_) => {
            let mut owned = t.replace('−', "-");
            if decimal_comma {
                owned = owned.replace(',', ".");
            }
            owned.parse().map_err(|_| NumberError::NotANumber)?
        }
    };
    if value.is_finite() {
        Ok(value)
    } else {
        Err(NumberError::NonFinite)
    }
}

/// A plain decimal (`-12.345`, `.5`, `7`) of at most 15 digits, read as the integer of
/// its digits divided by a power of ten: both are exact doubles (below 2^53 and 10^22),
/// and IEEE division rounds once, so the value is the correctly rounded one that
/// `str::parse` gives (Clinger's fast path), without its general machinery.
fn plain_decimal(t: &str) -> Option<f64> {
    const POW10: [f64; 16] = [
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
    ];
    let (negative, digits) = match t.as_bytes() {
        [b'-', rest @ ..] => (true, rest),
        [b'+', rest @ ..] => (false, rest),
        rest => (false, rest),
    };
    let (mut mantissa, mut count, mut decimals, mut point) = (0u64, 0usize, 0usize, false);
    for &b in digits {
        match b {
            // Past 15 digits the fast path cannot be exact (and the mantissa would
            // overflow at 20): `str::parse` reads it.
            b'0'..=b'9' if count == 15 => return None,
            b'0'..=b'9' => {
                mantissa = mantissa * 10 + u64::from(b - b'0');
                count += 1;
                decimals += usize::from(point);
            }
            b'.' if !point => point = true,
            _ => return None,
        }
    }
    if count == 0 {
        return None;
    }
    let value = mantissa as f64 / POW10[decimals];
    Some(if negative { -value } else { value })
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NumberError {
    NotANumber,
    NonFinite,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers() {
        assert_eq!(parse_number(" -1.5 ", false), Ok(-1.5));
        assert_eq!(parse_number("-1,5", true), Ok(-1.5));
        assert_eq!(parse_number("−2.5", false), Ok(-2.5));
        assert_eq!(parse_number("-.047", false), Ok(-0.047));
        assert_eq!(parse_number("NaN", false), Err(NumberError::NonFinite));
        assert_eq!(parse_number("inf", false), Err(NumberError::NonFinite));
        assert_eq!(parse_number("1,5", false), Err(NumberError::NotANumber));
        assert_eq!(parse_number("", false), Err(NumberError::NotANumber));
        assert_eq!(parse_number("-", false), Err(NumberError::NotANumber));
        assert_eq!(parse_number(".", false), Err(NumberError::NotANumber));
        assert_eq!(parse_number("1.2.3", false), Err(NumberError::NotANumber));
        assert_eq!(parse_number("1e3", false), Ok(1000.0));
    }

    /// The fast path gives the value `str::parse` gives, bit for bit.
    #[test]
    fn plain_decimals_are_parsed_as_std_parses_them() {
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let digits = (x % 15 + 1) as usize;
            let mantissa = x % 10u64.pow(digits as u32);
            let text = format!("{mantissa:0digits$}");
            let cut = (x >> 40) as usize % (digits + 1);
            let sign = if x & 1 == 0 { "-" } else { "" };
            let text = format!("{sign}{}.{}", &text[..cut], &text[cut..]);
            let want: f64 = text.parse().unwrap();
            assert_eq!(
                plain_decimal(&text).map(f64::to_bits),
                Some(want.to_bits()),
                "{text}"
            );
        }
        assert_eq!(plain_decimal("1234567890123456"), None);
        // Found by fuzzing: 22 digits overflowed the mantissa before the count was checked.
        assert_eq!(plain_decimal("8184467440737095516168"), None);
        assert_eq!(
            parse_number("8184467440737095516168", false),
            Ok(8.184467440737095e21)
        );
        assert_eq!(plain_decimal("-0"), Some(-0.0));
    }
}
