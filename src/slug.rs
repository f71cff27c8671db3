//! File-name-safe slugs and the small stable hash they use.

/// Turns any text into a file-name-safe slug: lower-case ASCII letters, digits and `-`; never
/// empty, never `.`/`..`, at most 64 characters.
pub fn slugify(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut dash = false;
    for ch in text.chars() {
        if ch.is_ascii_alphanumeric() {
            out.push(ch.to_ascii_lowercase());
            dash = false;
        } else if !dash && !out.is_empty() {
            out.push('-');
            dash = true;
        }
        if out.len() >= 64 {
            break;
        }
    }
    while out.ends_with('-') {
        out.pop();
    }
    if out.is_empty() || !text.is_ascii() {
        // Non-ASCII names (Japanese component names) get a stable hash so two of them never
        // collide on the same ASCII remainder.
        let h = format!("{:08x}", fnv1a(text.as_bytes()) as u32);
        if out.is_empty() {
            return format!("x-{h}");
        }
        out.push('-');
        out.push_str(&h);
    }
    out
}

/// 64-bit FNV-1a: a tiny, stable hash for deterministic slugs, cache names and checksums (not
/// for security).
pub fn fnv1a(bytes: &[u8]) -> u64 {
    fnv1a_from(FNV1A_START, bytes)
}

/// The start of [`fnv1a`] (its offset basis), for [`fnv1a_from`].
pub const FNV1A_START: u64 = 0xcbf2_9ce4_8422_2325;

/// [`fnv1a`] continued from `h` over `bytes` (a hash of several pieces, or of a stream).
pub fn fnv1a_from(mut h: u64, bytes: &[u8]) -> u64 {
    for b in bytes {
        h ^= u64::from(*b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    h
}
