//! Byte scans that test sixteen bytes per step, for the readers' and writers' fast paths.

/// Bytes tested per step by [`run_len`].
const BLOCK: usize = 16;

/// The length of the longest prefix of `b` whose bytes all satisfy a test, given twice:
/// `block` for sixteen bytes at once and `byte` for one.
///
/// Whole blocks are tested as a fixed-size loop without early exit: the compiler turns it into
/// a few vector compares when `block` is made of comparisons joined by `&` and `|` (no `&&`, no
/// table lookup). The rest, and the first block with a byte that fails, are searched byte by
/// byte with `byte`, which may be a table lookup (one load, where the comparisons of `block`
/// cost several instructions per byte).
#[inline(always)]
pub fn run_len(
    b: &[u8],
    block: impl Fn(u8) -> bool + Copy,
    byte: impl Fn(u8) -> bool + Copy,
) -> usize {
    let mut at = 0;
    for chunk in b.chunks_exact(BLOCK) {
        // `chunks_exact` gives chunks of exactly BLOCK bytes, so the conversion holds.
        let Ok(chunk) = <&[u8; BLOCK]>::try_from(chunk) else {
            break;
        };
        let mut all = true;
        for &c in chunk {
            all &= block(c);
        }
        if !all {
            break;
        }
        at += BLOCK;
    }
    at + b[at..]
        .iter()
        .position(|&c| !byte(c))
        .unwrap_or(b.len() - at)
}

#[cfg(test)]
mod tests {
    use super::run_len;

    proptest::proptest! {
        /// The block-wise scan stops where a byte-by-byte scan stops, at any length and place.
        #[test]
        fn run_len_matches_a_plain_scan(b in proptest::collection::vec(proptest::sample::select(&[b'a', b' ', b'\n', b'<', 0xe3][..]), 0..70)) {
            let keep = |c: u8| (c == b'a') | (c == b' ') | (c == b'\n');
            let plain = b.iter().position(|&c| !keep(c)).unwrap_or(b.len());
            proptest::prop_assert_eq!(run_len(&b, keep, keep), plain);
        }
    }
}
