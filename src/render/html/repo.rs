//! The repository around the profiles: the `source-url` setting, a template such as
//! `https://github.com/org/repo/blob/main/{path}` that turns the "Source" of a component page
//! into a link to the file in its repository.

/// The URL of `path` (input-relative, `/`-separated) under `template`: every `{path}` is
/// replaced by the path with each segment percent-encoded (RFC 3986 unreserved characters and
/// `/` stay as they are). `None` when the template has no `{path}` (a link to the same page
/// for every component would be wrong), still has a `{commit}` (only a `[[source]]`'s pinned
/// commit fills it in: [`pinned_source_url`]; a link with the placeholder in it would be
/// broken) or is not an http(s) URL (a `javascript:` URL must never reach a page).
pub fn source_url(template: &str, path: &str) -> Option<String> {
    let t = template.trim();
    let scheme_ok = t.starts_with("https://") || t.starts_with("http://");
    if !scheme_ok || !t.contains("{path}") || t.contains("{commit}") {
        return None;
    }
    let mut enc = String::with_capacity(path.len());
    for b in path.replace('\\', "/").bytes() {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' => {
                enc.push(b as char)
            }
            _ => enc.push_str(&format!("%{b:02X}")),
        }
    }
    Some(t.replace("{path}", enc.trim_start_matches('/')))
}

/// The URL of a file of a `[[source]]` repository: `template` with `{commit}` (40 hex digits,
/// else no link) and `{path}` (the path in the repository) replaced as [`source_url`] does.
pub fn pinned_source_url(template: &str, commit: &str, path: &str) -> Option<String> {
    if commit.len() != 40 || !commit.bytes().all(|b| b.is_ascii_hexdigit()) {
        return None;
    }
    source_url(&template.replace("{commit}", commit), path)
}

/// The HTML of a "Source" value linked to `url` (both escaped).
pub fn source_link_html(url: &str, path: &str) -> String {
    format!(
        "<a href=\"{}\"><code>{}</code></a>",
        super::svg::esc(url),
        super::svg::esc(path)
    )
}

/// The "Source" link of a document of the catalogue: into its `[[source]]` repository at the
/// pinned commit with the source's template, else `template` (`source-url`) with `source`, its
/// input-relative path.
pub fn document_source_url(
    sources: &[crate::model::SourceInfo],
    origin: Option<&crate::model::Origin>,
    source: &str,
    template: Option<&str>,
) -> Option<String> {
    match origin {
        Some(o) => sources
            .iter()
            .find(|s| s.name == o.source)
            .and_then(|s| s.source_url.as_deref())
            .and_then(|t| pinned_source_url(t, &o.commit, &o.path)),
        None => template.and_then(|t| source_url(t, source)),
    }
}

/// The link of a source file read beside a component's profile (`file` as shown, in the
/// profile's folder below): as [`document_source_url`], the file's path in the repository
/// being the profile's folder there joined with the file's place below the profile's folder.
pub fn sibling_source_url(
    sources: &[crate::model::SourceInfo],
    origin: Option<&crate::model::Origin>,
    profile: &str,
    file: &str,
    template: Option<&str>,
) -> Option<String> {
    match origin {
        Some(o) => {
            // `<name>/<path in the repository>`: the shown prefix is what the origin's path
            // lacks.
            let prefix = profile.strip_suffix(o.path.as_str())?;
            let in_repo = file.strip_prefix(prefix)?;
            let o = crate::model::Origin {
                path: in_repo.to_string(),
                ..o.clone()
            };
            document_source_url(sources, Some(&o), file, template)
        }
        None => template.and_then(|t| source_url(t, file)),
    }
}

/// The link of a document's file as a commit of its history had it (`commit`, `path` in the
/// repository), when the template (its source's, else `template`) has `{commit}`.
pub fn history_file_url(
    sources: &[crate::model::SourceInfo],
    origin: Option<&crate::model::Origin>,
    template: Option<&str>,
    commit: &str,
    path: &str,
) -> Option<String> {
    let template = match origin {
        Some(o) => sources
            .iter()
            .find(|s| s.name == o.source)
            .and_then(|s| s.source_url.as_deref()),
        None => template,
    }?;
    template
        .contains("{commit}")
        .then(|| pinned_source_url(template, commit, path))
        .flatten()
}

/// [`history_file_url`] for the commits of one document (from `origin`, else the input
/// directory with `template`), as the history views take it: a commit and a path in.
pub fn history_file_urls<'a>(
    sources: &'a [crate::model::SourceInfo],
    origin: Option<&'a crate::model::Origin>,
    template: Option<&'a str>,
) -> impl Fn(&str, &str) -> Option<String> + 'a {
    move |commit, path| history_file_url(sources, origin, template, commit, path)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `{commit}` is a source's pinned commit: a template of the input directory that has one
    /// links nothing rather than a URL with the placeholder in it.
    #[test]
    fn commit_placeholder_only_with_a_pinned_commit() {
        let t = "https://github.com/o/r/blob/{commit}/{path}";
        assert_eq!(source_url(t, "a/RTC.xml"), None);
        let c = "0123456789abcdef0123456789abcdef01234567";
        assert_eq!(
            pinned_source_url(t, c, "a/RTC.xml").as_deref(),
            Some("https://github.com/o/r/blob/0123456789abcdef0123456789abcdef01234567/a/RTC.xml")
        );
        assert_eq!(pinned_source_url(t, "HEAD", "a/RTC.xml"), None);
    }

    #[test]
    fn github_and_gitlab_templates() {
        assert_eq!(
            source_url(
                "https://github.com/org/repo/blob/main/{path}",
                "vision/Usb Camera/RTC.xml"
            )
            .as_deref(),
            Some("https://github.com/org/repo/blob/main/vision/Usb%20Camera/RTC.xml")
        );
        assert_eq!(
            source_url(
                "https://gitlab.com/org/repo/-/blob/main/profiles/{path}",
                "画像/RTC.xml"
            )
            .as_deref(),
            Some("https://gitlab.com/org/repo/-/blob/main/profiles/%E7%94%BB%E5%83%8F/RTC.xml")
        );
    }

    #[test]
    fn unsafe_or_pathless_templates_give_no_link() {
        assert_eq!(source_url("javascript:alert(1)//{path}", "a.xml"), None);
        assert_eq!(source_url("https://github.com/org/repo", "a.xml"), None);
        let h = source_link_html("https://x.org/?a=1&b=\"2\"", "<a>.xml");
        assert!(h.contains("&amp;b=&quot;2&quot;") && h.contains("&lt;a&gt;.xml"));
    }
}
