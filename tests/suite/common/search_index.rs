//! The site's search index read back from its files (`search-index.js` and `search/*.js`,
//! see `render/html/search.rs`): each entry whole again, as one list.

use std::path::Path;

/// One entry: what a result shows and its tokens by group (name, identifiers, prose).
#[derive(Debug, Clone)]
pub struct Entry {
    pub kind: String,
    pub name: String,
    pub href: String,
    pub meta: String,
    pub summary: String,
    pub groups: [Vec<String>; 3],
}

pub struct Index {
    /// The first file, parsed: `e`, `kinds`, `s`, `b`, `d`, `v`.
    pub first: serde_json::Value,
    pub entries: Vec<Entry>,
    /// The port files (`search/p<N>.js`) merged: `{d: [type…], i: [interface…]}`.
    pub ports: serde_json::Value,
    /// Every file's text, by path below the site.
    pub files: Vec<(String, String)>,
}

impl Index {
    /// The entry named `name` (the first one).
    pub fn entry(&self, name: &str) -> &Entry {
        self.entries
            .iter()
            .find(|e| e.name == name)
            .unwrap_or_else(|| panic!("{name} is indexed"))
    }

    /// All the files' text, one after the other (for "is this written anywhere").
    pub fn text(&self) -> String {
        self.files.iter().map(|(_, t)| t.as_str()).collect()
    }
}

/// The data of `RTCDOC_SHARD("kind",n,data);`.
fn shard(text: &str) -> serde_json::Value {
    let json = text
        .strip_prefix("RTCDOC_SHARD(")
        .and_then(|t| t.trim_end().strip_suffix(");"))
        .and_then(|t| t.splitn(3, ',').nth(2))
        .unwrap_or_else(|| panic!("RTCDOC_SHARD(…); in {text:.80}"));
    serde_json::from_str(json).expect("shard JSON")
}

/// Reads the index of the site at `site`.
pub fn read(site: &Path) -> Index {
    let first_text =
        std::fs::read_to_string(site.join("search-index.js")).expect("search-index.js");
    let first: serde_json::Value = serde_json::from_str(
        first_text
            .trim_end()
            .strip_prefix("window.RTCDOC_INDEX=")
            .and_then(|s| s.strip_suffix(';'))
            .expect("window.RTCDOC_INDEX=…;"),
    )
    .expect("the first file's JSON");
    let mut files = vec![("search-index.js".to_string(), first_text)];
    let mut names: Vec<String> = std::fs::read_dir(site.join("search"))
        .expect("search/")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    for n in names {
        let text = std::fs::read_to_string(site.join("search").join(&n)).expect("readable");
        files.push((format!("search/{n}"), text));
    }
    let get = |p: &str| -> serde_json::Value {
        shard(
            &files
                .iter()
                .find(|(n, _)| n == p)
                .unwrap_or_else(|| panic!("{p} written"))
                .1,
        )
    };
    let heads = first["e"].as_array().expect("e").clone();
    let block = first["d"].as_u64().expect("d") as usize;
    let mut entries: Vec<Entry> = heads
        .iter()
        .enumerate()
        .map(|(n, h)| {
            // The href without its kind's folder and `.html`, or `/` and all of it.
            let short = h[2].as_str().expect("href");
            let href = match short.strip_prefix('/') {
                Some(all) => all.to_string(),
                None => format!(
                    "{}{short}.html",
                    first["h"][h[0].as_str().expect("kind")]
                        .as_str()
                        .expect("a folder")
                ),
            };
            let det = get(&format!("search/e{}.js", n / block));
            let d = &det[n % block];
            Entry {
                kind: h[0].as_str().expect("kind").into(),
                name: h[1].as_str().expect("name").into(),
                href,
                meta: d[0].as_str().expect("meta").into(),
                summary: d[1].as_str().expect("summary").into(),
                groups: Default::default(),
            }
        })
        .collect();
    let starts = first["s"].as_array().expect("s").len();
    for i in 0..starts {
        // [token, posting…, token, posting…], postings as differences.
        let (mut token, mut p) = (String::new(), 0);
        for item in get(&format!("search/t{i}.js")).as_array().expect("tokens") {
            match item.as_u64() {
                Some(d) => {
                    p += d;
                    let (n, g) = ((p / 3) as usize, (p % 3) as usize);
                    entries[n].groups[g].push(token.clone());
                }
                None => {
                    token = item.as_str().expect("a token").to_string();
                    p = 0;
                }
            }
        }
    }
    for e in &mut entries {
        for g in &mut e.groups {
            g.sort();
        }
    }
    // The port files, merged: a type is in the file of each of its keys, listed once here.
    let mut ports = serde_json::json!({"d": [], "i": []});
    for n in 0..first["p"].as_u64().expect("p") {
        let part = get(&format!("search/p{n}.js"));
        for kind in ["d", "i"] {
            for t in part[kind].as_array().expect("types") {
                let list = ports[kind].as_array_mut().expect("a list");
                if !list.iter().any(|o| o[0] == t[0]) {
                    list.push(t.clone());
                }
            }
        }
    }
    Index {
        first,
        entries,
        ports,
        files,
    }
}
