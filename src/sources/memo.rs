//! What git answered about a pinned commit, kept in the cache: a commit never changes, so what
//! rtcdoc reads of it (the files of a source, the history of a file up to it) does not either,
//! and a warm build takes it from here without running git.
//!
//! Each answer is one file below its mirror (`<mirror>/rtcdoc/<kind>/<hash of the key>`, so
//! that deleting a mirror deletes its answers): a magic line, the key, the value, then the
//! value's length and an FNV-1a checksum of all that precedes it. It is written to a temporary
//! file and renamed into place, so a build killed while writing leaves no half answer; one whose
//! key, length or checksum does not match (corrupt, cut, or another key of the same hash) is
//! deleted and read from git again. Nothing is kept of a shallow mirror: deepening it changes
//! the history of its commits.

use std::io::Write;
use std::path::{Path, PathBuf};

const MAGIC: &[u8] = b"rtcdoc-memo 1\n";

use crate::slug::{fnv1a_from as fnv_from, FNV1A_START as FNV_START};

/// A hash of git's configuration outside the system one (which rtcdoc's git never reads): the
/// global files, the `GIT_CONFIG_*` settings of the environment, and `mirror`'s own `config`.
/// Part of the key of an answer that git's configuration may change (a history's
/// `git log --follow` and its rename detection). Files the configuration includes are not read.
pub fn config_stamp(mirror: &Path) -> u64 {
    static GLOBAL: std::sync::OnceLock<u64> = std::sync::OnceLock::new();
    let global = *GLOBAL.get_or_init(|| {
        let mut h = FNV_START;
        let var = |k: &str| std::env::var_os(k).map(|v| v.to_string_lossy().into_owned());
        let mut files: Vec<PathBuf> = Vec::new();
        match var("GIT_CONFIG_GLOBAL") {
            Some(g) => files.push(PathBuf::from(g)),
            None => {
                let home = var("HOME").map(PathBuf::from);
                match var("XDG_CONFIG_HOME") {
                    Some(x) => files.push(PathBuf::from(x).join("git/config")),
                    None => files.extend(home.as_ref().map(|h| h.join(".config/git/config"))),
                }
                files.extend(home.map(|h| h.join(".gitconfig")));
            }
        }
        let mut vars: Vec<(String, String)> = std::env::vars_os()
            .map(|(k, v)| {
                (
                    k.to_string_lossy().into_owned(),
                    v.to_string_lossy().into_owned(),
                )
            })
            .filter(|(k, _)| k.starts_with("GIT_CONFIG"))
            .collect();
        vars.sort();
        for (k, v) in vars {
            {
                h = fnv_from(h, k.as_bytes());
                h = fnv_from(h, v.as_bytes());
                h = fnv_from(h, b"\0");
            }
        }
        for f in files {
            h = fnv_from(h, f.to_string_lossy().as_bytes());
            h = fnv_from(h, &std::fs::read(&f).unwrap_or_default());
            h = fnv_from(h, b"\0");
        }
        h
    });
    fnv_from(
        global,
        &std::fs::read(mirror.join("config")).unwrap_or_default(),
    )
}

/// The folder of `kind`'s answers of `mirror`, or `None` when the mirror's answers are not
/// kept (a shallow mirror, or no mirror).
pub fn folder(mirror: &Path, kind: &str) -> Option<PathBuf> {
    (mirror.join("objects").is_dir() && !mirror.join("shallow").exists())
        .then(|| mirror.join("rtcdoc").join(kind))
}

/// The file of `key` in `dir`.
fn file_of(dir: &Path, key: &str) -> PathBuf {
    dir.join(format!("{:016x}", fnv_from(FNV_START, key.as_bytes())))
}

/// The value kept for `key` in `dir`, if a whole and matching one is there (a damaged one is
/// deleted).
pub fn recall(dir: &Path, key: &str) -> Option<Vec<u8>> {
    let path = file_of(dir, key);
    let bytes = std::fs::read(&path).ok()?;
    let value = check(&bytes, key);
    if value.is_none() {
        let _ = std::fs::remove_file(&path);
    }
    value.map(<[u8]>::to_vec)
}

/// Whether `dir` holds an answer for `key` (without reading it).
pub fn has(dir: &Path, key: &str) -> bool {
    file_of(dir, key).is_file()
}

/// The value of a kept file's `bytes` when they are whole and answer `key`.
fn check<'a>(bytes: &'a [u8], key: &str) -> Option<&'a [u8]> {
    let n = bytes.len();
    let head = MAGIC.len() + 8 + key.len();
    if n < head + 16 || !bytes.starts_with(MAGIC) {
        return None;
    }
    let word = |at: usize| -> Option<u64> {
        Some(u64::from_le_bytes(bytes.get(at..at + 8)?.try_into().ok()?))
    };
    let key_len = usize::try_from(word(MAGIC.len())?).ok()?;
    if key_len != key.len() || &bytes[MAGIC.len() + 8..head] != key.as_bytes() {
        return None;
    }
    let value_len = usize::try_from(word(n - 16)?).ok()?;
    if value_len != n - 16 - head || word(n - 8)? != fnv_from(FNV_START, &bytes[..n - 8]) {
        return None;
    }
    Some(&bytes[head..n - 16])
}

/// An answer being written: [`Writer::finish`] puts it in place, dropping it leaves nothing.
pub struct Writer {
    file: std::io::BufWriter<tempfile::NamedTempFile>,
    hash: u64,
    len: u64,
    path: PathBuf,
    failed: bool,
}

impl Writer {
    /// A new answer for `key` in `dir` (created if needed); `None` when it cannot be written.
    pub fn new(dir: &Path, key: &str) -> Option<Writer> {
        std::fs::create_dir_all(dir).ok()?;
        let tmp = tempfile::Builder::new()
            .prefix(".tmp-")
            .tempfile_in(dir)
            .ok()?;
        let mut w = Writer {
            file: std::io::BufWriter::new(tmp),
            hash: FNV_START,
            len: 0,
            path: file_of(dir, key),
            failed: false,
        };
        w.raw(MAGIC);
        w.raw(&(key.len() as u64).to_le_bytes());
        w.raw(key.as_bytes());
        w.len = 0;
        Some(w)
    }

    fn raw(&mut self, bytes: &[u8]) {
        self.hash = fnv_from(self.hash, bytes);
        self.len += bytes.len() as u64;
        self.failed |= self.file.write_all(bytes).is_err();
    }

    /// Appends `bytes` to the value.
    pub fn write(&mut self, bytes: &[u8]) {
        self.raw(bytes);
    }

    /// Puts the answer in place (atomically: a rename); false when it could not be written.
    pub fn finish(mut self) -> bool {
        let len = self.len;
        self.raw(&len.to_le_bytes());
        let sum = self.hash;
        self.failed |= self.file.write_all(&sum.to_le_bytes()).is_err();
        if self.failed {
            return false;
        }
        let Ok(tmp) = self.file.into_inner() else {
            return false;
        };
        tmp.persist(&self.path).is_ok()
    }
}

/// Keeps `value` for `key` in `dir` (best effort: a cache that cannot be written is skipped).
pub fn remember(dir: &Path, key: &str, value: &[u8]) {
    if let Some(mut w) = Writer::new(dir, key) {
        w.write(value);
        w.finish();
    }
}

/// A length-prefixed field appended to `out`.
pub fn put_field(out: &mut Vec<u8>, bytes: &[u8]) {
    out.extend((bytes.len() as u64).to_le_bytes());
    out.extend(bytes);
}

/// The next length-prefixed field of `rest`, which moves past it.
pub fn take_field<'a>(rest: &mut &'a [u8]) -> Option<&'a [u8]> {
    let len = usize::try_from(u64::from_le_bytes(rest.get(..8)?.try_into().ok()?)).ok()?;
    let field = rest.get(8..8usize.checked_add(len)?)?;
    *rest = &rest[8 + len..];
    Some(field)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn answers_are_recalled_whole_and_damaged_ones_dropped() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path().join("a");
        remember(&dir, "k1", b"value one");
        assert_eq!(recall(&dir, "k1").as_deref(), Some(&b"value one"[..]));
        assert!(recall(&dir, "k2").is_none());
        // Cut, then flipped: not trusted, and deleted.
        let f = file_of(&dir, "k1");
        let bytes = std::fs::read(&f).unwrap();
        std::fs::write(&f, &bytes[..bytes.len() - 3]).unwrap();
        assert!(recall(&dir, "k1").is_none());
        assert!(!f.exists());
        let mut flipped = bytes.clone();
        let at = flipped.len() - 20;
        flipped[at] ^= 1;
        std::fs::write(&f, &flipped).unwrap();
        assert!(recall(&dir, "k1").is_none());
        // A writer dropped unfinished leaves nothing.
        let mut w = Writer::new(&dir, "k3").unwrap();
        w.write(b"half");
        drop(w);
        assert!(recall(&dir, "k3").is_none());
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
        let mut buf = Vec::new();
        put_field(&mut buf, b"ab");
        put_field(&mut buf, b"");
        let mut rest = &buf[..];
        assert_eq!(take_field(&mut rest), Some(&b"ab"[..]));
        assert_eq!(take_field(&mut rest), Some(&b""[..]));
        assert_eq!(take_field(&mut rest), None);
    }
}
