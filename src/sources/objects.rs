//! One long-lived `git cat-file --batch` of a repository ([`ObjectReader`]): the blobs, and the
//! trees walked in-process, of a pinned commit, instead of a `git ls-tree` and a `git cat-file`
//! per reader. Every read is bounded: a blob is cut at its limit plus one byte (the readers
//! then report it as too large, as on disk), a tree walk stops with a named error past
//! [`MAX_TREE_ENTRIES`] files or [`MAX_TREE_DEPTH`] levels, and an object name that git could
//! read as something else (a newline or NUL in it, a leading `-`) is refused before git sees
//! it.

use anyhow::{bail, Context, Result};
use std::io::{BufRead, BufReader, Read, Write};
use std::path::Path;
use std::process::{Child, ChildStdin, ChildStdout, Stdio};

/// Most files a tree walk lists (a hostile repository of millions of files is named, not read).
pub const MAX_TREE_ENTRIES: usize = 500_000;
/// Deepest folder nesting a tree walk enters.
pub const MAX_TREE_DEPTH: usize = 256;
/// Largest tree object read (a tree of [`MAX_TREE_ENTRIES`] entries is far smaller).
const MAX_TREE_BYTES: u64 = 64 << 20;
/// Bytes of object names sent to git before its answers are read: less than the smallest pipe
/// buffer, so that neither side waits for the other.
const REQUEST_CHUNK: usize = 8 << 10;

/// An object as git gave it: its type, its whole size, and its bytes (cut at the read's bound).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Object {
    /// The object's id (what a name such as `refs/heads/main^{commit}` resolved to).
    pub oid: String,
    pub kind: String,
    pub size: u64,
    pub data: Vec<u8>,
}

/// A file of a tree walk, as `git ls-tree -r` lists it: mode (`100644`, `120000`, `160000`…),
/// type (`blob`, `commit` for a submodule), object id, and its path from the top of the
/// repository.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TreeEntry {
    pub mode: String,
    pub kind: &'static str,
    pub oid: String,
    pub path: String,
}

/// A running `git cat-file --batch` of one repository. Dropped: its input is closed and git is
/// waited for.
pub struct ObjectReader {
    child: Child,
    stdin: Option<ChildStdin>,
    out: BufReader<ChildStdout>,
}

/// Refuses an object name git would not read as one name: empty, with a newline, NUL or other
/// control character (a second request), or starting with `-`.
pub fn check_name(name: &str) -> Result<()> {
    if name.is_empty() || name.starts_with('-') || name.chars().any(char::is_control) {
        bail!("refused object name {name:?}: empty, starting with `-` or with a control character");
    }
    Ok(())
}

impl ObjectReader {
    /// Starts `git cat-file --batch` in the repository `git_dir` (the current one when `None`),
    /// with [`super::git_command`]'s safe environment.
    pub fn open(git_dir: Option<&Path>) -> Result<ObjectReader> {
        ObjectReader::spawn(super::git_command(git_dir))
    }

    /// Starts `git cat-file --batch` with `c`: a [`super::git_command`] with its repository
    /// (and current directory) set.
    pub fn spawn(mut c: std::process::Command) -> Result<ObjectReader> {
        c.args(["cat-file", "--batch"])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null());
        let mut child = c
            .spawn()
            .context("cannot run `git cat-file` ([[source]] repositories need git on the PATH)")?;
        let stdin = child.stdin.take();
        let out = match child.stdout.take() {
            Some(o) => BufReader::with_capacity(1 << 16, o),
            None => {
                let _ = child.kill();
                let _ = child.wait();
                bail!("git cat-file: no pipe from git");
            }
        };
        Ok(ObjectReader { child, stdin, out })
    }

    /// The object `name`, its bytes cut at `max + 1`; `None` when the repository lacks it.
    pub fn read(&mut self, name: &str, max: u64) -> Result<Option<Object>> {
        let mut got = None;
        self.read_each(&[name], max, &mut |_, o| {
            got = o;
            Ok(())
        })?;
        Ok(got)
    }

    /// The objects `names`, in order, each handed to `visit` as it arrives (`None`: missing),
    /// its bytes cut at `max + 1`. The names are sent in chunks, each answered before the next.
    pub fn read_each(
        &mut self,
        names: &[&str],
        max: u64,
        visit: &mut dyn FnMut(usize, Option<Object>) -> Result<()>,
    ) -> Result<()> {
        for n in names {
            check_name(n)?;
        }
        let mut start = 0;
        while start < names.len() {
            let mut end = start;
            let mut request = String::new();
            while end < names.len() && (end == start || request.len() < REQUEST_CHUNK) {
                request.push_str(names[end]);
                request.push('\n');
                end += 1;
            }
            let stdin = self
                .stdin
                .as_mut()
                .context("git cat-file: no pipe to git")?;
            stdin
                .write_all(request.as_bytes())
                .and_then(|()| stdin.flush())
                .context("git cat-file stopped reading")?;
            for (i, name) in names.iter().enumerate().take(end).skip(start) {
                let o = self.answer(name, max)?;
                visit(i, o)?;
            }
            start = end;
        }
        Ok(())
    }

    /// Git's answer to one request: a header (`<oid> <type> <size>`, or `<name> missing`), the
    /// bytes and a newline.
    fn answer(&mut self, name: &str, max: u64) -> Result<Option<Object>> {
        let mut head = Vec::new();
        let n = (&mut self.out)
            .take(4096)
            .read_until(b'\n', &mut head)
            .context("git cat-file stopped answering")?;
        if n == 0 || !head.ends_with(b"\n") {
            bail!("git cat-file gave no answer for {name}");
        }
        let head = String::from_utf8_lossy(&head[..head.len() - 1]).to_string();
        let f: Vec<&str> = head.split(' ').collect();
        let (kind, size) = match (f.get(1), f.get(2).and_then(|s| s.parse::<u64>().ok())) {
            (Some(k), Some(s)) if f.len() == 3 => (k.to_string(), s),
            _ if head.ends_with(" missing") || head.ends_with(" ambiguous") => return Ok(None),
            _ => bail!("git cat-file answered `{head}` for {name}"),
        };
        let keep = size.min(max.saturating_add(1));
        let mut data = Vec::with_capacity(usize::try_from(keep.min(1 << 24)).unwrap_or(0));
        (&mut self.out).take(keep).read_to_end(&mut data)?;
        std::io::copy(&mut (&mut self.out).take(size - keep), &mut std::io::sink())?;
        let mut newline = [0u8; 1];
        self.out.read_exact(&mut newline)?;
        if u64::try_from(data.len()).ok() != Some(keep) {
            bail!("git cat-file gave {name} short");
        }
        Ok(Some(Object {
            oid: f[0].to_string(),
            kind,
            size,
            data,
        }))
    }

    /// The commit `what` names (a ref, a tag, a full or abbreviated id), as `git rev-parse
    /// --verify 'what^{commit}'` resolves it; `None` when it names none.
    pub fn commit_of(&mut self, what: &str) -> Result<Option<String>> {
        let o = self.read(&format!("{what}^{{commit}}"), 0)?;
        Ok(o.filter(|o| o.kind == "commit")
            .map(|o| o.oid)
            .filter(|c| matches!(c.len(), 40 | 64) && c.bytes().all(|b| b.is_ascii_hexdigit())))
    }

    /// The files of `commit` below the folder `path` (`""`: all), as `git ls-tree -r
    /// --full-tree -- path` lists them; `None` when the repository lacks the commit, or `path`
    /// is no folder of it. More than [`MAX_TREE_ENTRIES`] files or [`MAX_TREE_DEPTH`] levels is
    /// an error that says so.
    pub fn walk(&mut self, commit: &str, path: &str) -> Result<Option<Vec<TreeEntry>>> {
        if !commit.bytes().all(|b| b.is_ascii_hexdigit()) || commit.len() < 40 {
            bail!("refused commit {commit:?}: not a full object id");
        }
        let Some(root) = self.read(&format!("{commit}^{{tree}}"), MAX_TREE_BYTES)? else {
            return Ok(None);
        };
        let hash_len = commit.len() / 2;
        let mut tree = tree_of(root, "the commit's tree")?;
        let mut prefix = String::new();
        for seg in path.split('/').filter(|s| !s.is_empty()) {
            let entries = parse_tree(&tree, hash_len)?;
            let Some(e) = entries
                .into_iter()
                .find(|e| e.name == seg.as_bytes() && e.mode == "40000")
            else {
                return Ok(None);
            };
            prefix.push_str(seg);
            prefix.push('/');
            let Some(sub) = self.read(&e.oid, MAX_TREE_BYTES)? else {
                return Ok(None);
            };
            tree = tree_of(sub, &prefix)?;
        }
        let mut out = Vec::new();
        self.walk_into(
            &tree,
            hash_len,
            &prefix,
            prefix.matches('/').count(),
            &mut out,
        )?;
        Ok(Some(out))
    }

    /// The files of the tree `data` (at `prefix`, `depth` levels down) appended to `out`, in
    /// `git ls-tree -r` order.
    fn walk_into(
        &mut self,
        data: &[u8],
        hash_len: usize,
        prefix: &str,
        depth: usize,
        out: &mut Vec<TreeEntry>,
    ) -> Result<()> {
        if depth > MAX_TREE_DEPTH {
            bail!(
                "the repository's folders nest deeper than {MAX_TREE_DEPTH} levels (at `{}`); rtcdoc reads no deeper: set `path` to the folder of the profiles",
                prefix.trim_end_matches('/')
            );
        }
        for e in parse_tree(data, hash_len)? {
            let path = format!("{prefix}{}", String::from_utf8_lossy(&e.name));
            if e.mode == "40000" {
                let Some(sub) = self.read(&e.oid, MAX_TREE_BYTES)? else {
                    bail!(
                        "the tree {} of `{path}` is missing from the repository",
                        e.oid
                    );
                };
                let sub = tree_of(sub, &path)?;
                self.walk_into(&sub, hash_len, &format!("{path}/"), depth + 1, out)?;
                continue;
            }
            if out.len() >= MAX_TREE_ENTRIES {
                bail!(
                    "the repository has more than {MAX_TREE_ENTRIES} files (at `{path}`); rtcdoc reads no more: set `path` to the folder of the profiles"
                );
            }
            let kind = if e.mode == "160000" { "commit" } else { "blob" };
            out.push(TreeEntry {
                mode: e.mode,
                kind,
                oid: e.oid,
                path,
            });
        }
        Ok(())
    }
}

impl Drop for ObjectReader {
    fn drop(&mut self) {
        drop(self.stdin.take());
        let _ = self.child.wait();
    }
}

/// The bytes of a tree object, or an error when `o` is another type or was cut.
fn tree_of(o: Object, at: &str) -> Result<Vec<u8>> {
    if o.kind != "tree" {
        bail!("`{at}` is a {} where git has a tree", o.kind);
    }
    if u64::try_from(o.data.len()).ok() != Some(o.size) {
        bail!("the tree of `{at}` is larger than {MAX_TREE_BYTES} bytes; rtcdoc does not read it");
    }
    Ok(o.data)
}

/// One entry of a tree object.
struct RawTreeEntry {
    mode: String,
    name: Vec<u8>,
    oid: String,
}

/// The entries of a tree object's bytes: `<mode> <name>\0<hash>` each.
fn parse_tree(data: &[u8], hash_len: usize) -> Result<Vec<RawTreeEntry>> {
    let mut out = Vec::new();
    let mut rest = data;
    while !rest.is_empty() {
        let bad = || anyhow::anyhow!("a malformed tree object (at entry {})", out.len() + 1);
        let space = memchr::memchr(b' ', rest).ok_or_else(bad)?;
        let mode = std::str::from_utf8(&rest[..space]).map_err(|_| bad())?;
        let after = &rest[space + 1..];
        let nul = memchr::memchr(0, after).ok_or_else(bad)?;
        let name = &after[..nul];
        let hash = after.get(nul + 1..nul + 1 + hash_len).ok_or_else(bad)?;
        if mode.is_empty() || !mode.bytes().all(|b| b.is_ascii_digit()) || name.is_empty() {
            return Err(bad());
        }
        let mut oid = String::with_capacity(hash_len * 2);
        for b in hash {
            use std::fmt::Write as _;
            let _ = write!(oid, "{b:02x}");
        }
        out.push(RawTreeEntry {
            mode: mode.to_string(),
            name: name.to_vec(),
            oid,
        });
        rest = &after[nul + 1 + hash_len..];
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_that_git_would_misread_are_refused() {
        for bad in ["", "-x", "a\nb", "a\0b", "a\rb"] {
            assert!(check_name(bad).is_err(), "{bad:?}");
        }
        check_name("0123abcd^{tree}").unwrap();
    }

    #[test]
    fn a_reader_refuses_odd_names_and_goes_on_reading() {
        let tmp = tempfile::tempdir().unwrap();
        let git = |args: &[&str]| {
            let ok = std::process::Command::new("git")
                .args(["-c", "user.name=t", "-c", "user.email=t@example.org"])
                .args(args)
                .current_dir(tmp.path())
                .env("GIT_CONFIG_NOSYSTEM", "1")
                .env("GIT_CONFIG_GLOBAL", "/dev/null")
                .output()
                .unwrap();
            assert!(ok.status.success(), "{args:?}");
            String::from_utf8(ok.stdout).unwrap()
        };
        git(&["init", "-q"]);
        std::fs::create_dir_all(tmp.path().join("a/b")).unwrap();
        std::fs::write(tmp.path().join("a/b/RTC.xml"), "<x/>").unwrap();
        std::fs::write(tmp.path().join("top.txt"), "0123456789").unwrap();
        git(&["add", "-A"]);
        git(&["commit", "-q", "-m", "one"]);
        let head = git(&["rev-parse", "HEAD"]).trim().to_string();
        let mut r = ObjectReader::open(Some(&tmp.path().join(".git"))).unwrap();
        for bad in ["HEAD\nHEAD", "-h", "HEAD\0x", ""] {
            assert!(r.read(bad, 10).is_err(), "{bad:?}");
        }
        assert!(r.walk("HEAD", "").is_err(), "a commit that is no full id");
        assert_eq!(r.commit_of("HEAD").unwrap().as_deref(), Some(head.as_str()));
        assert_eq!(r.commit_of("refs/heads/nothing").unwrap(), None);
        let all = r.walk(&head, "").unwrap().unwrap();
        let paths: Vec<&str> = all.iter().map(|e| e.path.as_str()).collect();
        assert_eq!(paths, ["a/b/RTC.xml", "top.txt"]);
        let below = r.walk(&head, "a").unwrap().unwrap();
        assert_eq!(below.len(), 1);
        assert_eq!(
            r.walk(&head, "top.txt").unwrap(),
            None,
            "a file is no folder"
        );
        assert_eq!(r.walk(&head, "nope").unwrap(), None);
        assert_eq!(
            r.walk(&"0".repeat(40), "").unwrap(),
            None,
            "a missing commit"
        );
        // Cut at the bound plus one byte.
        let top = &all[1].oid;
        let o = r.read(top, 3).unwrap().unwrap();
        assert_eq!((o.size, o.data.as_slice()), (10, &b"0123"[..]));
    }

    #[test]
    fn tree_objects_parse_and_malformed_ones_are_named() {
        let mut t = b"100644 a.txt\0".to_vec();
        t.extend([0xab; 20]);
        t.extend(b"40000 dir\0");
        t.extend([0x01; 20]);
        let e = parse_tree(&t, 20).unwrap();
        assert_eq!(e.len(), 2);
        assert_eq!(e[0].mode, "100644");
        assert_eq!(e[0].oid, "ab".repeat(20));
        assert_eq!(e[1].name, b"dir");
        assert!(parse_tree(&t[..t.len() - 1], 20).is_err());
        assert!(parse_tree(b"x y\0", 20).is_err());
    }
}
