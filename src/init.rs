//! `rtcdoc init`: finding an OpenRTM installation's IDL directory to suggest in the new
//! `rtcdoc.toml`.
//!
//! OpenRTM-aist installs the IDL of its data types and interfaces (BasicDataType.idl,
//! ExtendedDataTypes.idl, InterfaceDataTypes.idl, RTC.idl, …) in
//! `<prefix>/include/openrtm-<version>/rtm/idl/` on Linux and macOS (`/usr` for the distribution
//! packages, `/usr/local` for a source build) and in
//! `C:\Program Files\OpenRTM-aist\<version>\rtm\idl\` on Windows, whose installer also sets
//! `RTM_ROOT` to the version's directory. [`detect`] looks in those places, in a fixed order,
//! and returns the first directory holding at least one `*.idl` file; `rtcdoc init` writes it
//! into the configuration as a commented line. Only `init` looks: a build reads the IDL that
//! the configuration and the command line name, never what happens to be installed.
//!
//! Everything the search reads from the environment goes through a function parameter, so it
//! is testable without touching the machine's real installation: the variables `RTM_ROOT`,
//! `OPENRTM_DIR` / `OpenRTM_DIR` (CMake's package directory), and `RTCDOC_OPENRTM_PREFIXES`,
//! a path list that replaces the built-in prefixes (`/usr/local`, `/usr`, `/opt/openrtm-aist`,
//! `/opt/local`, `/opt/homebrew`; on Windows `%ProgramFiles%\OpenRTM-aist` and
//! `%ProgramFiles(x86)%\OpenRTM-aist`).

use std::ffi::OsString;
use std::path::{Path, PathBuf};

/// The environment variable whose path list replaces the built-in installation prefixes.
pub const PREFIXES_VAR: &str = "RTCDOC_OPENRTM_PREFIXES";

/// An IDL directory found, and how.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Detected {
    /// The directory (holds at least one `*.idl` file).
    pub dir: PathBuf,
    /// How it was found, for the comment in the configuration: `$RTM_ROOT`, `the prefix /usr`, ….
    pub via: String,
}

/// Where to look, in order: `(directory that may hold IDL, how it was found)`. A directory
/// named `openrtm-*` or a version (`OpenRTM-aist\2.0.0`) below a root stands for every
/// version installed there, newest first.
fn roots(env: &dyn Fn(&str) -> Option<OsString>) -> Vec<(PathBuf, String)> {
    let mut out: Vec<(PathBuf, String)> = Vec::new();
    let set = |name: &str| env(name).filter(|v| !v.is_empty()).map(PathBuf::from);
    if let Some(root) = set("RTM_ROOT") {
        // The installer's RTM_ROOT is the version's directory (`…\OpenRTM-aist\1.2.2\`).
        out.push((root.join("rtm").join("idl"), "$RTM_ROOT".into()));
        for dir in versioned(&root.join("include"), "openrtm-") {
            out.push((dir.join("rtm").join("idl"), "$RTM_ROOT".into()));
        }
    }
    for var in ["OPENRTM_DIR", "OpenRTM_DIR"] {
        let Some(dir) = set(var) else { continue };
        // CMake's package directory: `<prefix>/lib/cmake/OpenRTM` (or `…/lib/openrtm-2.0/cmake`)
        // on Linux, `…\OpenRTM-aist\2.0.0\cmake` on Windows. The prefix is up to three levels up.
        let mut up: Option<&Path> = Some(dir.as_path());
        for _ in 0..4 {
            let Some(d) = up else { break };
            out.push((d.join("rtm").join("idl"), format!("${var}")));
            for v in versioned(&d.join("include"), "openrtm-") {
                out.push((v.join("rtm").join("idl"), format!("${var}")));
            }
            up = d.parent();
        }
    }
    let prefixes: Vec<PathBuf> = match env(PREFIXES_VAR) {
        Some(list) => std::env::split_paths(&list)
            .filter(|p| !p.as_os_str().is_empty())
            .collect(),
        None => default_prefixes(env),
    };
    for prefix in prefixes {
        let how = format!("the prefix {}", prefix.display());
        // Linux and macOS: <prefix>/include/openrtm-<ver>/rtm/idl.
        for v in versioned(&prefix.join("include"), "openrtm-") {
            out.push((v.join("rtm").join("idl"), how.clone()));
        }
        // Windows: <Program Files>\OpenRTM-aist\<ver>\rtm\idl (the prefix is the OpenRTM-aist
        // folder), and a prefix that is itself one version's directory.
        for v in versioned(&prefix, "") {
            out.push((v.join("rtm").join("idl"), how.clone()));
        }
        out.push((prefix.join("rtm").join("idl"), how));
    }
    out
}

/// The built-in prefixes of this platform.
fn default_prefixes(env: &dyn Fn(&str) -> Option<OsString>) -> Vec<PathBuf> {
    if cfg!(windows) {
        let mut v: Vec<PathBuf> = ["ProgramFiles", "ProgramFiles(x86)"]
            .iter()
            .filter_map(|k| env(k).filter(|v| !v.is_empty()))
            .map(|p| PathBuf::from(p).join("OpenRTM-aist"))
            .collect();
        if v.is_empty() {
            v.push(PathBuf::from(r"C:\Program Files\OpenRTM-aist"));
        }
        v
    } else {
        [
            "/usr/local",
            "/usr",
            "/opt/openrtm-aist",
            "/opt/local",
            "/opt/homebrew",
        ]
        .iter()
        .map(PathBuf::from)
        .collect()
    }
}

/// The subdirectories of `dir` named `<prefix><version>` (a version: digits and dots, e.g.
/// `openrtm-2.0`, `1.2.2`), newest version first; names equal in version by name.
fn versioned(dir: &Path, prefix: &str) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut found: Vec<(Vec<u64>, String, PathBuf)> = entries
        .flatten()
        .filter(|e| e.path().is_dir())
        .filter_map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            let rest = name
                .get(..prefix.len())
                .filter(|h| h.eq_ignore_ascii_case(prefix))
                .map(|_| &name[prefix.len()..])?;
            let version = parse_version(rest)?;
            Some((version, name.clone(), e.path()))
        })
        .collect();
    found.sort_by(|a, b| b.0.cmp(&a.0).then_with(|| a.1.cmp(&b.1)));
    found.into_iter().map(|(_, _, p)| p).collect()
}

/// `2.0`, `1.2.2`, `2.0.0-RELEASE` → its numbers; anything not starting with a digit → `None`.
fn parse_version(s: &str) -> Option<Vec<u64>> {
    let head: &str = s
        .split(|c: char| !(c.is_ascii_digit() || c == '.'))
        .next()
        .unwrap_or("");
    if !head.starts_with(|c: char| c.is_ascii_digit()) {
        return None;
    }
    Some(
        head.split('.')
            .filter(|p| !p.is_empty())
            .map(|p| p.parse().unwrap_or(u64::MAX))
            .collect(),
    )
}

/// Whether `dir` holds at least one `*.idl` file (directly).
fn holds_idl(dir: &Path) -> bool {
    std::fs::read_dir(dir).is_ok_and(|entries| {
        entries.flatten().any(|e| {
            e.path().is_file()
                && e.path()
                    .extension()
                    .is_some_and(|x| x.eq_ignore_ascii_case("idl"))
        })
    })
}

/// The first OpenRTM IDL directory found (see the module documentation for the order), reading
/// the environment through `env`.
pub fn detect(env: &dyn Fn(&str) -> Option<OsString>) -> Option<Detected> {
    roots(env)
        .into_iter()
        .find(|(dir, _)| holds_idl(dir))
        .map(|(dir, via)| Detected { dir, via })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    /// A temporary directory with an OpenRTM IDL directory (one IDL file) at each of `rels`,
    /// and those directories.
    fn fake_installs(rels: &[&str]) -> (tempfile::TempDir, Vec<PathBuf>) {
        let t = tempfile::tempdir().unwrap();
        let dirs = rels
            .iter()
            .map(|rel| {
                let d = t.path().join(rel);
                std::fs::create_dir_all(&d).unwrap();
                std::fs::write(d.join("BasicDataType.idl"), "module RTC {};\n").unwrap();
                d
            })
            .collect();
        (t, dirs)
    }

    fn env_of(vars: &[(&str, &Path)]) -> impl Fn(&str) -> Option<OsString> {
        let m: HashMap<String, OsString> = vars
            .iter()
            .map(|(k, v)| (k.to_string(), v.as_os_str().to_owned()))
            .collect();
        move |k| m.get(k).cloned()
    }

    #[test]
    fn finds_the_newest_version_below_a_prefix() {
        let (t, dirs) =
            fake_installs(&["include/openrtm-1.2/rtm/idl", "include/openrtm-2.0/rtm/idl"]);
        // A version directory without IDL does not count.
        std::fs::create_dir_all(t.path().join("include/openrtm-10.0/rtm/idl")).unwrap();
        let d = detect(&env_of(&[(PREFIXES_VAR, t.path())])).unwrap();
        assert_eq!(d.dir, dirs[1]);
        assert_eq!(d.via, format!("the prefix {}", t.path().display()));
    }

    #[test]
    fn nothing_installed_is_none() {
        let t = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(t.path().join("include/openrtm-2.0/rtm/idl")).unwrap();
        assert_eq!(detect(&env_of(&[(PREFIXES_VAR, t.path())])), None);
    }

    #[test]
    fn rtm_root_comes_before_the_prefixes() {
        let (t, dirs) = fake_installs(&[
            "usr/include/openrtm-2.0/rtm/idl",
            "OpenRTM-aist/1.2.2/rtm/idl",
        ]);
        let root = t.path().join("OpenRTM-aist/1.2.2");
        let prefix = t.path().join("usr");
        let d = detect(&env_of(&[("RTM_ROOT", &root), (PREFIXES_VAR, &prefix)])).unwrap();
        assert_eq!((&d.dir, d.via.as_str()), (&dirs[1], "$RTM_ROOT"));
    }

    #[test]
    fn windows_layout_below_program_files() {
        let (t, dirs) =
            fake_installs(&["OpenRTM-aist/1.2.2/rtm/idl", "OpenRTM-aist/2.0.0/rtm/idl"]);
        let prefix = t.path().join("OpenRTM-aist");
        let d = detect(&env_of(&[(PREFIXES_VAR, &prefix)])).unwrap();
        assert_eq!(d.dir, dirs[1]);
    }

    #[test]
    fn cmake_package_directory_leads_to_its_prefix() {
        let (t, dirs) = fake_installs(&["include/openrtm-2.0/rtm/idl"]);
        let cmake = t.path().join("lib/cmake/OpenRTM");
        std::fs::create_dir_all(&cmake).unwrap();
        let empty = t.path().join("nothing");
        let d = detect(&env_of(&[("OPENRTM_DIR", &cmake), (PREFIXES_VAR, &empty)])).unwrap();
        assert_eq!((&d.dir, d.via.as_str()), (&dirs[0], "$OPENRTM_DIR"));
    }

    #[test]
    fn versions_compare_as_numbers() {
        assert_eq!(parse_version("2.0.0"), Some(vec![2, 0, 0]));
        assert_eq!(parse_version("1.10-beta"), Some(vec![1, 10]));
        assert_eq!(parse_version("x1"), None);
        assert!(parse_version("1.10") > parse_version("1.9"));
    }
}
