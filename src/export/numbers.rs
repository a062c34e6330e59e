//! Numbers as people read them in captions, labels and written pictures: six significant
//! digits at most with thousands grouped, and a range's two ends to a thousandth of its width.

/// A number shortened for captions: 6 significant digits at most, thousands grouped with
/// commas (1312.918088 → "1,312.92"), trailing zeros dropped; in scientific notation from 1e9 up
/// and below 1e-4.
pub(crate) fn short_number(value: f64) -> String {
    let magnitude = value.abs();
    if !value.is_finite() {
        return value.to_string();
    }
    if magnitude >= 1e9 || (magnitude > 0.0 && magnitude < 1e-4) {
        return format!("{value:.4e}");
    }
    // Six significant digits: the decimals after the first digit's place.
    let first_digit = if magnitude > 0.0 {
        magnitude.log10().floor()
    } else {
        0.0
    };
    let decimals = (5.0 - first_digit).clamp(0.0, 10.0) as usize;
    trimmed(&grouped(value, decimals))
}

/// The decimals that resolve a thousandth of `span` (0 to 6): a depth range 5.7 wide gets 3
/// decimals, one 772 wide gets 1, so the two ends of a range read alike and no digit is noise.
pub(crate) fn decimals_for_span(span: f64) -> usize {
    let span = span.abs();
    if !(span.is_finite() && span > 0.0) {
        return 6;
    }
    (-(span / 1000.0).log10()).ceil().clamp(0.0, 6.0) as usize
}

/// The two ends of a range, each with the decimals [`decimals_for_span`] gives its width, and
/// thousands grouped ("10.301", "16.037"); [`short_number`] for ends of 1e9 and more.
pub(crate) fn range_ends(low: f64, high: f64) -> [String; 2] {
    let decimals = decimals_for_span(high - low);
    [low, high].map(|value| with_decimals(value, decimals))
}

/// `value` with `decimals` decimals and thousands grouped; [`short_number`] from 1e9 up (and
/// for what is not a finite number).
pub(crate) fn with_decimals(value: f64, decimals: usize) -> String {
    if value.is_finite() && value.abs() < 1e9 {
        grouped(value, decimals)
    } else {
        short_number(value)
    }
}

/// `value` with `decimals` decimals and its thousands grouped with commas.
pub(crate) fn grouped(value: f64, decimals: usize) -> String {
    let text = format!("{:.*}", decimals, value.abs());
    let (whole, fraction) = text
        .split_once('.')
        .map_or((text.as_str(), None), |(w, f)| (w, Some(f)));
    let mut out = String::new();
    if value.is_sign_negative() && text.chars().any(|c| c.is_ascii_digit() && c != '0') {
        out.push('-');
    }
    for (index, digit) in whole.chars().enumerate() {
        if index > 0 && (whole.len() - index).is_multiple_of(3) {
            out.push(',');
        }
        out.push(digit);
    }
    if let Some(fraction) = fraction {
        out.push('.');
        out.push_str(fraction);
    }
    out
}

/// `text` without trailing zeros after a decimal point (nor the point itself).
fn trimmed(text: &str) -> String {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_numbers_for_captions() {
        assert_eq!(short_number(9.0), "9");
        assert_eq!(short_number(14.5), "14.5");
        assert_eq!(short_number(-2.0), "-2");
        assert_eq!(short_number(1e12), "1.0000e12");
        // Six significant digits, thousands grouped.
        assert_eq!(short_number(540.954387), "540.954");
        assert_eq!(short_number(1312.918088), "1,312.92");
        assert_eq!(short_number(-1234567.0), "-1,234,567");
        assert_eq!(short_number(0.3333333), "0.333333");
        assert_eq!(short_number(-0.0000001), "-1.0000e-7");
        assert_eq!(short_number(-0.0), "0");
    }

    #[test]
    fn range_ends_resolve_a_thousandth_of_the_range() {
        assert_eq!(range_ends(10.300586, 16.036998), ["10.301", "16.037"]);
        assert_eq!(range_ends(540.954387, 1312.918088), ["541.0", "1,312.9"]);
        assert_eq!(range_ends(9.0, 10.0), ["9.000", "10.000"]);
        assert_eq!(range_ends(-2.5, 2.5), ["-2.500", "2.500"]);
        assert_eq!(with_decimals(1e200, 3), "1.0000e200");
        assert_eq!(decimals_for_span(0.0), 6);
        assert_eq!(decimals_for_span(1e-9), 6);
        assert_eq!(decimals_for_span(5000.0), 0);
    }
}
