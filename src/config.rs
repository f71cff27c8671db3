//! `rtcdoc.toml`: the project configuration.
//!
//! Every key is optional; command-line flags override the file, the file overrides the
//! defaults. Unknown keys are an error that names the key and its line, so a typo never goes
//! unnoticed. Paths in the file are relative to the file's directory.

use crate::i18n::Lang;
use crate::parse::Limits;
use crate::render::Format;
use anyhow::{Context, Result};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// File name looked for in the input directory and the current directory.
pub const FILE_NAME: &str = "rtcdoc.toml";

/// The contents of `rtcdoc.toml`, as written (all optional).
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct Config {
    /// Title of the catalogue.
    pub title: Option<String>,
    /// URL the site is published at (used in sitemap.xml).
    pub base_url: Option<String>,
    /// Directory of profiles (default: the directory holding the config file).
    pub input: Option<PathBuf>,
    /// Output directory.
    pub output: Option<PathBuf>,
    /// Output formats.
    pub formats: Option<Vec<Format>>,
    /// Theme directory overriding the built-in theme file by file.
    pub theme: Option<PathBuf>,
    /// Language of generated labels: `en` or `ja`.
    pub language: Option<Lang>,
    /// Globs of input-relative paths to take (default: everything).
    pub include: Option<Vec<String>>,
    /// Globs of input-relative paths to leave out.
    pub exclude: Option<Vec<String>>,
    /// More directories of IDL files, searched recursively (e.g. OpenRTM's `rtm/idl`).
    pub idl_path: Option<Vec<PathBuf>>,
    /// Fail the build on any profile error.
    pub strict: Option<bool>,
    /// Commits read per profile for its history (0: no history).
    pub history: Option<usize>,
    /// `[[source]]` repositories fetched and read at once (default: the number of cores).
    pub jobs: Option<usize>,
    /// Largest profile file accepted, in bytes.
    pub max_file_size: Option<u64>,
    /// Deepest nesting accepted.
    pub max_depth: Option<usize>,
    /// Settings of `rtcdoc serve`.
    pub serve: Option<ServeConfig>,
    /// Publish the host data of RT System profiles (host names, IORs, CORBA endpoints, naming
    /// paths), e.g. for an internal site.
    pub show_host_data: Option<bool>,
    /// URL template of a profile in its repository, with `{path}` (the input-relative path).
    pub source_url: Option<String>,
    /// Settings of the Markdown output.
    pub markdown: Option<MarkdownConfig>,
    /// `[[source]]` tables: git repositories documented at a pinned commit
    /// ([`crate::sources`]).
    pub source: Option<Vec<crate::sources::SourceConfig>>,
    /// `[implementation]`: how each component's code is found and compared with its profile
    /// ([`crate::implementation`]).
    pub implementation: Option<ImplementationConfig>,
    /// `[diff]`: the policy of `rtcdoc diff` (changes ignored, severities overridden;
    /// [`crate::diff::policy`]).
    pub diff: Option<crate::diff::policy::DiffConfig>,
    /// `[stability]`: marks of components, data types and interfaces by id, name or scoped
    /// name, over the profiles' `rtcdoc.stability` properties ([`crate::catalog::stability`]).
    pub stability: Option<std::collections::BTreeMap<String, toml::Spanned<StabilityConfig>>>,
    /// `stability` checked, with the place of each key (made by [`parse`]).
    #[serde(skip)]
    pub stability_marks: crate::catalog::stability::Settings,
}

/// One `[stability."KEY"]` table.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct StabilityConfig {
    /// `experimental`, `stable` or `deprecated`.
    pub status: toml::Spanned<String>,
    /// The version since which it is so.
    pub since: Option<String>,
    /// What to use instead.
    pub replacement: Option<String>,
    /// A free note.
    pub note: Option<String>,
}

/// `[stability]` checked: each status known, each key with its place in `text`.
fn stability_marks(
    table: &std::collections::BTreeMap<String, toml::Spanned<StabilityConfig>>,
    text: &str,
    file: &Path,
) -> Result<crate::catalog::stability::Settings> {
    use crate::model::stability::{Origin, Stability, Status};
    let at = |offset: usize| crate::model::Pos::at_offset(text, offset);
    let filled = |v: &Option<String>| {
        v.as_deref()
            .map(str::trim)
            .filter(|v| !v.is_empty())
            .map(str::to_string)
    };
    let mut marks = Vec::new();
    for (key, entry) in table {
        let e = entry.get_ref();
        let Some(status) = Status::parse(e.status.get_ref()) else {
            anyhow::bail!(
                "{}:{}: [stability] `{key}`: {}",
                file.display(),
                at(e.status.span().start),
                crate::catalog::stability::unknown_status(e.status.get_ref())
            );
        };
        if key.trim().is_empty() {
            anyhow::bail!(
                "{}:{}: [stability]: an empty key names nothing; write a component id or name, or a type's scoped name (`[stability.\"RTC::OldService\"]`)",
                file.display(),
                at(entry.span().start)
            );
        }
        marks.push(crate::catalog::stability::Mark {
            key: key.trim().to_string(),
            pos: Some(at(entry.span().start)),
            stability: Stability {
                status,
                since: filled(&e.since),
                replacement: filled(&e.replacement),
                note: filled(&e.note),
                origin: Origin::Config,
            },
        });
    }
    Ok(crate::catalog::stability::Settings {
        file: file.display().to_string(),
        marks,
    })
}

/// `[implementation]` settings.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct ImplementationConfig {
    /// Read and compare implementations (default true).
    pub check: Option<bool>,
    /// `[[implementation.component]]`: the files of components whose name or id matches
    /// `name` (a glob), relative to the profile's folder.
    pub component: Option<Vec<ImplementationFiles>>,
}

#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct ImplementationFiles {
    pub name: String,
    pub files: Vec<String>,
}

impl ImplementationConfig {
    /// The settings of a build (the size limit is filled in by the load).
    fn settings(&self, file: &Path) -> Result<crate::catalog::implementations::Settings> {
        let mut files = Vec::new();
        for c in self.component.iter().flatten() {
            let g = globset::Glob::new(&c.name).map_err(|e| {
                anyhow::anyhow!(
                    "{}: [[implementation.component]] name `{}` is not a valid glob ({e}); write a component name, an id, or a pattern such as `Camera*`",
                    file.display(),
                    c.name
                )
            })?;
            if let Some(bad) = c
                .files
                .iter()
                .find(|f| f.starts_with('/') || f.split(['/', '\\']).any(|s| s == ".."))
            {
                anyhow::bail!(
                    "{}: [[implementation.component]] `{}`: the file `{bad}` is outside the component's folder; name files relative to the folder of its RTC.xml, without `..`",
                    file.display(),
                    c.name
                );
            }
            files.push((g.compile_matcher(), c.files.clone()));
        }
        Ok(crate::catalog::implementations::Settings {
            enabled: self.check.unwrap_or(true),
            files,
            ..Default::default()
        })
    }
}

/// `[markdown]` settings.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct MarkdownConfig {
    /// System diagrams as SVG files (`svg`) or Mermaid blocks (`mermaid`).
    pub diagrams: Option<crate::render::DiagramFormat>,
}

/// `[serve]` settings.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
pub struct ServeConfig {
    pub port: Option<u16>,
    pub open: Option<bool>,
}

/// A configuration and the directory its relative paths are resolved against.
#[derive(Debug, Clone, Default)]
pub struct Loaded {
    pub config: Config,
    /// Directory of the file; `None` when no file was found.
    pub dir: Option<PathBuf>,
    /// The file read, if any.
    pub path: Option<PathBuf>,
}

impl Loaded {
    /// Resolves a path from the file against the file's directory (`input = "."` beside a
    /// file in `.` is `.`, not `./.`).
    pub fn resolve(&self, p: &Path) -> PathBuf {
        match &self.dir {
            Some(d) if p.is_relative() => d.join(p).components().collect(),
            _ => p.to_path_buf(),
        }
    }

    /// Limits with the file's values over the defaults.
    pub fn limits(&self) -> Limits {
        let d = Limits::default();
        Limits {
            max_file_size: self.config.max_file_size.unwrap_or(d.max_file_size),
            max_depth: self.config.max_depth.unwrap_or(d.max_depth),
        }
    }
}

/// Parses configuration text. Errors name the file, the line and column, and the key.
pub fn parse(text: &str, file: &Path) -> Result<Config> {
    let mut c = toml::from_str::<Config>(text).map_err(|e| {
        let pos = e.span().map_or(crate::model::Pos::new(1, 1), |s| {
            crate::model::Pos::at_offset(text, s.start)
        });
        let message = e.message().trim_end();
        anyhow::anyhow!(
            "{}:{pos}: {message}{}",
            file.display(),
            crate::diagnostic::unknown_field_hint(message)
        )
    })?;
    if let Some(i) = &c.implementation {
        i.settings(file)?;
    }
    if let Some(d) = &c.diff {
        let at = |span: std::ops::Range<usize>| {
            format!(
                "{}:{}",
                file.display(),
                crate::model::Pos::at_offset(text, span.start)
            )
        };
        crate::diff::policy::Policy::new(d, &at)?;
    }
    if let Some(table) = &c.stability {
        c.stability_marks = stability_marks(table, text, file)?;
    }
    Ok(c)
}

/// Reads `explicit` when given (it must exist), else the first `rtcdoc.toml` found in
/// `search` (in order); no file at all is fine and gives the defaults.
pub fn load(explicit: Option<&Path>, search: &[&Path]) -> Result<Loaded> {
    let path = match explicit {
        Some(p) => Some(p.to_path_buf()),
        None => search
            .iter()
            .map(|d| {
                if d.is_dir() {
                    d.join(FILE_NAME)
                } else {
                    d.with_file_name(FILE_NAME)
                }
            })
            .find(|p| p.is_file()),
    };
    let Some(path) = path else {
        return Ok(Loaded::default());
    };
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read configuration `{}`", path.display()))?;
    let config = parse(&text, &path)?;
    let dir = path.parent().map(|p| {
        if p.as_os_str().is_empty() {
            PathBuf::from(".")
        } else {
            p.to_path_buf()
        }
    });
    Ok(Loaded {
        config,
        dir,
        path: Some(path),
    })
}

/// The text `rtcdoc init` writes: every key, commented out, with its default.
pub fn template() -> String {
    template_for(None)
}

/// The `[[source]]` table the templates suggest (after their comments on it).
const SOURCE_EXAMPLE: &str = r#"# [[source]]
# git = "https://github.com/ORG/REPO.git"
# rev = "main"
# path = "components"
# name = "REPO"
# source-url = "https://git.example.org/ORG/REPO/blob/{commit}/{path}"
"#;

/// The text `rtcdoc init --language LANG` writes: [`template_for`] for English; for Japanese the
/// same keys in the same order, with Japanese comments and `language = "ja"` set (not commented
/// out), so that a Japanese project starts in Japanese.
pub fn template_in(lang: Lang, idl: Option<&crate::init::Detected>) -> String {
    match lang {
        Lang::En => template_for(idl),
        Lang::Ja => template_ja(idl),
    }
}

/// [`template`], with the OpenRTM IDL directory `rtcdoc init` found (if any) as the suggested
/// `idl-path`, still commented out: a build never depends on what is installed.
pub fn template_for(idl: Option<&crate::init::Detected>) -> String {
    let d = Limits::default();
    let idl = match idl {
        None => "# More directories of IDL files (data types, service interfaces), searched recursively; every
# *.idl below the input is read anyway. E.g. an OpenRTM installation's IDL:
# idl-path = [\"/usr/include/openrtm-2.0/rtm/idl\"]"
            .to_string(),
        Some(found) => format!(
            "# More directories of IDL files (data types, service interfaces), searched recursively; every
# *.idl below the input is read anyway. `rtcdoc init` found OpenRTM's IDL through {}:
# uncomment the line to document the types and interfaces defined there (RTC::TimedLong, …).
# idl-path = [{}]",
            found.via,
            crate::sources::lock::quoted(&found.dir.to_string_lossy())
        ),
    };
    format!(
        r#"# rtcdoc configuration. Every key is optional; command-line flags override this file.
# Paths are relative to this file's directory.

# Title of the catalogue (index page, book title, Doxygen project name).
# title = "RT-Component catalogue"

# URL the site is published at; used for absolute links in sitemap.xml, the Atom feed of the
# history (feed.xml) and the 404 page.
# base-url = "https://example.org/components/"

# Link "Source" on component pages to the file in its repository (and a component README's
# links to other files); {{path}} is the file's path relative to the input directory.
# GitHub: https://github.com/ORG/REPO/blob/main/{{path}}
# GitLab: https://gitlab.com/ORG/REPO/-/blob/main/{{path}}
# source-url = "https://github.com/ORG/REPO/blob/main/{{path}}"

# Directory searched for profiles (RTC.xml and the YAML form), recursively.
# input = "."

# Output directory. It is replaced on every successful build.
# output = "site"

# Output formats: "html", "markdown", "doxygen", "json", "manual". Several at once go to output/<format>/.
# formats = ["html"]

# A theme directory; any file in it replaces the built-in template or asset of the same name.
# theme = "my-theme"

# Language of generated labels: "en" or "ja". Profile text is always shown as written.
# language = "en"

# Globs (relative to input) of files to take, and to leave out (for example "old/**").
# include = ["**"]
# exclude = []

{idl}

# Fail without writing anything when a profile has an error.
# strict = false

# Limits against hostile input.
# max-file-size = {size}
# max-depth = {depth}

# Commits read per profile for its history (git, with RTCBuilder's backups); 0 turns it off.
# history = 100

# How many sources ([[source]]) are fetched and read at once (--jobs); default: the number of cores.
# jobs = 4

# RT System profiles carry the host names, IORs and CORBA endpoints of the machine they were
# saved on; system pages and catalog.json leave them out unless this is true (an internal site).
# show-host-data = false

# Markdown output: system wiring diagrams as SVG files beside the pages ("svg") or as Mermaid
# blocks in them ("mermaid").
# [markdown]
# diagrams = "svg"

# rtcdoc serve
# [serve]
# port = 3000
# open = false

# rtcdoc diff: changes that never fail it (codes, names or categories such as DIFF3xx: see
# `rtcdoc diff --explain CODE`), codes taken back out of an ignored category, codes ignored in
# some files only (globs relative to the input), and other severities for codes.
# [diff]
# ignore = ["DIFF3xx"]
# except = ["DIFF304"]
# ignore-only = {{ "DIFF103" = ["Legacy/**"] }}
# severity = {{ "DIFF201" = "breaking" }}

# Stability marks: a component (its id or name), a data type or a service interface (its scoped
# name) experimental, stable or deprecated. Pages show it, `rtcdoc diff` reports the breaking
# changes of experimental items as warnings, `rtcdoc check` warns where a deprecated type is
# used (RTC407). Wins over a profile's own `rtcdoc.stability` property.
# [stability."RTC::OldService"]
# status = "deprecated"
# since = "2.0"
# replacement = "RTC::NewService"
# note = "Removed in 3.0."

# Git repositories to document besides (or, without `input`, instead of) the input directory,
# each pinned at a commit in rtcdoc.lock (`rtcdoc update` moves them). One table per repository.
# git: https://, ssh://, git@host:path, file:// or a local path. rev: a branch, tag or commit
# (default: the remote's default branch). path: the sub-folder to document. name: the first
# folder of its files in the catalogue (default: from the URL). source-url: the link of a file,
# with {{commit}} and {{path}} (derived for GitHub and GitLab https URLs).
{source_example}"#,
        size = d.max_file_size,
        depth = d.max_depth,
        source_example = SOURCE_EXAMPLE,
    )
}

/// The Japanese [`template_in`]: every key of [`template_for`], in its order, with the comments
/// in Japanese and `language = "ja"` uncommented.
fn template_ja(idl: Option<&crate::init::Detected>) -> String {
    let d = Limits::default();
    let idl = match idl {
        None => "# 追加で読み込む IDL ファイル (データ型、サービスインターフェース) のディレクトリ。再帰的に探索します。
# 入力以下の *.idl はこの設定がなくても読み込みます。例: OpenRTM のインストール先の IDL
# idl-path = [\"/usr/include/openrtm-2.0/rtm/idl\"]"
            .to_string(),
        Some(found) => {
            // `via` is `$RTM_ROOT`, `$OPENRTM_DIR` or `the prefix /usr`.
            let via = match found.via.strip_prefix("the prefix ") {
                Some(prefix) => format!("プレフィックス {prefix}"),
                None => found.via.clone(),
            };
            format!(
                "# 追加で読み込む IDL ファイル (データ型、サービスインターフェース) のディレクトリ。再帰的に探索します。
# 入力以下の *.idl はこの設定がなくても読み込みます。`rtcdoc init` が {via} から OpenRTM の IDL を
# 見つけました。そこで定義された型とインターフェース (RTC::TimedLong など) をドキュメントにするには、
# 次の行のコメントを外してください。
# idl-path = [{}]",
                crate::sources::lock::quoted(&found.dir.to_string_lossy())
            )
        }
    };
    format!(
        r#"# rtcdoc の設定ファイル。どのキーも省略でき、コマンドラインのフラグはこのファイルより優先されます。
# パスはこのファイルのあるディレクトリからの相対パスです。

# カタログのタイトル (索引ページ、ブックのタイトル、Doxygen のプロジェクト名)。
# title = "RTコンポーネント カタログ"

# サイトを公開する URL。sitemap.xml、履歴の Atom フィード (feed.xml)、404 ページの絶対リンクに使います。
# base-url = "https://example.org/components/"

# コンポーネントページの「ソース」を、リポジトリにあるそのファイルへのリンクにします (コンポーネントの
# README から他のファイルへのリンクにも使います)。{{path}} は入力ディレクトリからのファイルの相対パスです。
# GitHub: https://github.com/ORG/REPO/blob/main/{{path}}
# GitLab: https://gitlab.com/ORG/REPO/-/blob/main/{{path}}
# source-url = "https://github.com/ORG/REPO/blob/main/{{path}}"

# プロファイル (RTC.xml と YAML 形式) を再帰的に探すディレクトリ。
# input = "."

# 出力ディレクトリ。ビルドが成功するたびに置き換えられます。
# output = "site"

# 出力形式: "html"、"markdown"、"doxygen"、"json"、"manual"。複数指定すると output/<形式>/ に出力します。
# formats = ["html"]

# テーマのディレクトリ。ここにあるファイルが、同じ名前の組み込みテンプレート・アセットを置き換えます。
# theme = "my-theme"

# 生成するラベル (見出し、表の項目名、図、検索画面) の言語: "en" または "ja"。
# プロファイルの文章は常に書かれたとおりに表示します。
language = "ja"

# 読み込むファイルと除外するファイルの glob (input からの相対パス。例: "old/**")。
# include = ["**"]
# exclude = []

{idl}

# プロファイルにエラーが 1 つでもあれば、何も書き出さずに失敗します。
# strict = false

# 悪意のある入力に対する上限。
# max-file-size = {size}
# max-depth = {depth}

# プロファイルごとに履歴として読むコミットの数 (git と RTCBuilder のバックアップ)。0 で履歴を作りません。
# history = 100

# 同時に取得して読むソース ([[source]]) の数 (--jobs)。省略時はコア数です。
# jobs = 4

# RTシステムのプロファイルには、保存したマシンのホスト名、IOR、CORBA のエンドポイントが含まれます。
# システムのページと catalog.json は、これを true にしない限りそれらを公開しません (社内向けサイトなどで使用)。
# show-host-data = false

# Markdown 出力: RTシステムの接続図を、ページの横の SVG ファイル ("svg") にするか、
# ページ内の Mermaid のブロック ("mermaid") にするか。
# [markdown]
# diagrams = "svg"

# rtcdoc serve の設定
# [serve]
# port = 3000
# open = false

# rtcdoc diff: 失敗の理由にしない変更 (コード、名前、または DIFF3xx のような分類。`rtcdoc diff --explain CODE`
# を参照)、無視した分類から外すコード、一部のファイルでだけ無視するコード (入力からの相対パスの glob)、
# コードごとの重大度の変更。
# [diff]
# ignore = ["DIFF3xx"]
# except = ["DIFF304"]
# ignore-only = {{ "DIFF103" = ["Legacy/**"] }}
# severity = {{ "DIFF201" = "breaking" }}

# 安定性の指定: コンポーネント (ID または名前)、データ型、サービスインタフェース (スコープ付きの名前) を
# experimental (実験的)、stable (安定)、deprecated (非推奨) と指定します。ページに表示し、`rtcdoc diff` は
# 実験的な項目の破壊的変更を警告として報告し、`rtcdoc check` は非推奨の型を使う箇所で警告します (RTC407)。
# プロファイル自身の `rtcdoc.stability` プロパティより優先します。
# [stability."RTC::OldService"]
# status = "deprecated"
# since = "2.0"
# replacement = "RTC::NewService"
# note = "Removed in 3.0."

# 入力ディレクトリに加えて (`input` がなければその代わりに) ドキュメントにする git リポジトリ。
# それぞれ rtcdoc.lock のコミットに固定します (`rtcdoc update` で進めます)。リポジトリごとに 1 つの表を書きます。
# git: https://、ssh://、git@host:path、file:// またはローカルのパス。rev: ブランチ、タグまたはコミット
# (省略時はリモートのデフォルトブランチ)。path: ドキュメントにするサブフォルダ。name: カタログでのファイルの
# 最初のフォルダ名 (省略時は URL から)。source-url: ファイルへのリンク。{{commit}} と {{path}} を含めます
# (GitHub と GitLab の https の URL からは自動で作ります)。
{source_example}"#,
        size = d.max_file_size,
        depth = d.max_depth,
        source_example = SOURCE_EXAMPLE,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The keys a template sets or suggests (`key = ` lines, commented or not) and its tables.
    fn template_keys(t: &str) -> Vec<String> {
        t.lines()
            .map(|l| l.strip_prefix("# ").unwrap_or(l))
            .filter_map(|l| {
                if l.starts_with('[') {
                    Some(l.to_string())
                } else {
                    l.split_once(" = ")
                        .map(|(k, _)| k)
                        .filter(|k| !k.contains(' '))
                        .map(str::to_string)
                }
            })
            .collect()
    }

    /// A template with every commented-out key and table uncommented.
    fn uncommented(t: &str) -> String {
        t.lines()
            .map(|l| {
                l.strip_prefix("# ")
                    .filter(|r| r.contains(" = ") || r.starts_with('['))
                    .unwrap_or(l)
            })
            .collect::<Vec<_>>()
            .join("\n")
    }

    #[test]
    fn japanese_template_has_every_key_and_starts_in_japanese() {
        let found = crate::init::Detected {
            dir: PathBuf::from("/usr/include/openrtm-2.0/rtm/idl"),
            via: "the prefix /usr".into(),
        };
        for idl in [None, Some(&found)] {
            let en = template_in(Lang::En, idl);
            let ja = template_in(Lang::Ja, idl);
            assert_eq!(en, template_for(idl));
            // The same keys, in the same order.
            assert_eq!(template_keys(&ja), template_keys(&en), "{ja}");
            // Only `language` is set.
            let c = parse(&ja, Path::new("x")).unwrap();
            assert_eq!(
                c,
                Config {
                    language: Some(Lang::Ja),
                    ..Config::default()
                }
            );
            // Uncommenting every key gives a valid file too.
            let c = parse(&uncommented(&ja), Path::new("x")).unwrap();
            assert_eq!(c.title.as_deref(), Some("RTコンポーネント カタログ"));
            assert_eq!(c.serve.unwrap().port, Some(3000));
        }
        let ja = template_in(Lang::Ja, Some(&found));
        assert!(
            ja.contains("プレフィックス /usr から OpenRTM の IDL"),
            "{ja}"
        );
        assert!(ja.contains("# idl-path = [\"/usr/include/openrtm-2.0/rtm/idl\"]"));
    }

    #[test]
    fn template_parses_to_defaults_and_uncommented_template_is_valid() {
        let t = template();
        assert_eq!(parse(&t, Path::new("x")).unwrap(), Config::default());
        // Uncommenting every key gives a valid file too.
        let c = parse(&uncommented(&t), Path::new("x")).unwrap();
        assert_eq!(c.formats, Some(vec![Format::Html]));
        assert_eq!(c.language, Some(Lang::En));
        assert_eq!(c.serve.as_ref().and_then(|s| s.port), Some(3000));
        let d = c.diff.as_ref().expect("[diff]");
        assert_eq!(d.ignore.as_ref().map(Vec::len), Some(1));
        assert_eq!(d.severity.as_ref().map(|s| s.len()), Some(1));
        // A setting with a default shows it (the others show an example): uncommented, the
        // build's options are the defaults.
        let file = Loaded {
            config: c,
            dir: None,
            path: None,
        };
        let (all, none) = (
            build_options(&file, &Overrides::default()),
            build_options(&Loaded::default(), &Overrides::default()),
        );
        assert_eq!(all.load.exclude, none.load.exclude);
        assert_eq!(all.load.include, vec!["**".to_string()], "every file");
        assert!(none.load.include.is_empty(), "no include: every file");
        assert_eq!(
            (all.strict, all.load.history, &all.site.title, all.formats),
            (
                none.strict,
                none.load.history,
                &none.site.title,
                none.formats
            )
        );
        assert_eq!(
            format!("{:?}", all.load.limits),
            format!("{:?}", none.load.limits)
        );
    }

    #[test]
    fn template_with_a_detected_idl_directory_suggests_it_commented() {
        for dir in [
            r"C:\Program Files\OpenRTM-aist\1.2.2\rtm\idl",
            "/opt/x \"y\"/include/openrtm-2.0/rtm/idl",
        ] {
            let found = crate::init::Detected {
                dir: PathBuf::from(dir),
                via: "$RTM_ROOT".into(),
            };
            let t = template_for(Some(&found));
            assert!(t.contains("found OpenRTM's IDL through $RTM_ROOT"), "{t}");
            // Commented: the file still means the defaults.
            assert_eq!(parse(&t, Path::new("x")).unwrap(), Config::default());
            let on = t.replace("# idl-path = ", "idl-path = ");
            assert_eq!(
                parse(&on, Path::new("x")).unwrap().idl_path,
                Some(vec![PathBuf::from(dir)])
            );
        }
        // Nothing found: the template as always.
        assert_eq!(template_for(None), template());
        assert!(template().contains("# idl-path = [\"/usr/include/openrtm-2.0/rtm/idl\"]"));
    }

    #[test]
    fn unknown_keys_are_errors_with_their_line() {
        let e = parse("title = \"x\"\n\ntitel = \"y\"\n", Path::new("rtcdoc.toml")).unwrap_err();
        let msg = e.to_string();
        assert!(msg.starts_with("rtcdoc.toml:3:1:"), "{msg}");
        assert!(msg.contains("titel"), "{msg}");
        let e = parse("[serve]\nprot = 1\n", Path::new("c.toml")).unwrap_err();
        assert!(e.to_string().starts_with("c.toml:2:1:"), "{e}");
    }

    #[test]
    fn bad_values_are_errors() {
        assert!(parse("formats = [\"pdf\"]", Path::new("c")).is_err());
        assert!(parse("language = \"fr\"", Path::new("c")).is_err());
        assert!(parse("max-depth = -1", Path::new("c")).is_err());
    }
}

/// The `[[source]]` repositories of the configuration, pinned ([`crate::sources::prepare`]):
/// at the commits of `rtcdoc.lock` beside the file, fetched into the cache as needed, the lock
/// written when it changed. `update`: the sources to move to their current rev (`Some(&[])`:
/// all). No sources: nothing is done (and no lock is written).
pub fn pin_sources(
    file: &Loaded,
    mode: &crate::sources::Mode,
    update: Option<&[String]>,
    progress: &dyn crate::progress::Progress,
) -> Result<(Vec<crate::sources::Pinned>, crate::sources::lock::Changes)> {
    let configs = file.config.source.as_deref().unwrap_or_default();
    let base = file.dir.clone().unwrap_or_else(|| PathBuf::from("."));
    if configs.is_empty() {
        if update.is_some() {
            anyhow::bail!(
                "{} has no [[source]] table: there is nothing to update or lock",
                file.path.as_deref().map_or_else(
                    || "there is no rtcdoc.toml; it".to_string(),
                    |p| format!("`{}`", p.display())
                )
            );
        }
        return Ok((Vec::new(), Default::default()));
    }
    let sources = crate::sources::check_all(configs, &base).with_context(|| {
        format!(
            "{}",
            file.path
                .as_deref()
                .unwrap_or(Path::new(FILE_NAME))
                .display()
        )
    })?;
    // The commands the errors suggest (`rtcdoc update`) name the file unless it is the one
    // they would find: `rtcdoc.toml` in the current directory.
    let in_cwd = |p: &Path| {
        p.file_name() == Some(std::ffi::OsStr::new(FILE_NAME))
            && p.parent()
                .is_none_or(|d| d.as_os_str().is_empty() || d == Path::new("."))
    };
    let mode = crate::sources::Mode {
        config: file.path.clone().filter(|p| !in_cwd(p)),
        jobs: mode.jobs.or(file.config.jobs),
        ..mode.clone()
    };
    crate::sources::prepare(
        &sources,
        &base.join(crate::sources::lock::FILE_NAME),
        &mode,
        update,
        progress,
    )
}

/// Values given on the command line: the settings of `rtcdoc.toml` that have a flag, each one
/// given winning over the file's (a path as given, not against the file's folder), and the
/// flag that only the command line has.
#[derive(Debug, Clone, Default)]
pub struct Overrides {
    pub settings: Config,
    /// `--allow-empty`: an input without profiles is not an error.
    pub allow_empty: bool,
}

/// The catalogue title when none is configured, in the UI language.
pub fn default_title(lang: Lang) -> String {
    match lang {
        Lang::En => crate::render::SiteOptions::default().title,
        Lang::Ja => "RTコンポーネント カタログ".to_string(),
    }
}

/// The input when the command line names none: the configuration's `input`, else the
/// configuration file's folder, else the current directory (`build`, `check` and `serve` alike).
pub fn default_input(file: &Loaded) -> PathBuf {
    file.config
        .input
        .as_deref()
        .map(|p| file.resolve(p))
        .or_else(|| file.dir.clone())
        .unwrap_or_else(|| PathBuf::from("."))
}

/// The `[stability]` marks of a build of `input`: their findings name the file relative to the
/// input's root (as every finding's file is), or by its absolute path when it is outside.
fn stability_for(file: &Loaded, input: &Path) -> crate::catalog::stability::Settings {
    let mut s = file.config.stability_marks.clone();
    if let Some(path) = &file.path {
        let root = crate::build::input_root(input);
        s.file = match path.strip_prefix(&root) {
            Ok(rel) => rel.to_string_lossy().replace('\\', "/"),
            Err(_) => std::path::absolute(path)
                .unwrap_or_else(|_| path.clone())
                .to_string_lossy()
                .into_owned(),
        };
    }
    s
}

/// Combines defaults, the configuration file and command-line overrides (in rising order of
/// precedence) into the options of a build.
pub fn build_options(file: &Loaded, overrides: &Overrides) -> crate::build::BuildOptions {
    let (c, cli) = (&file.config, &overrides.settings);
    let input = cli.input.clone().unwrap_or_else(|| default_input(file));
    let stability = stability_for(file, &input);
    let output = cli
        .output
        .clone()
        .or_else(|| c.output.as_deref().map(|p| file.resolve(p)))
        .unwrap_or_else(|| file.resolve(Path::new("site")));
    let limits = file.limits();
    crate::build::BuildOptions {
        input,
        output,
        formats: cli
            .formats
            .clone()
            .or_else(|| c.formats.clone())
            .unwrap_or_else(|| vec![Format::Html]),
        strict: cli.strict.or(c.strict).unwrap_or(false),
        load: crate::build::LoadOptions {
            include: cli
                .include
                .clone()
                .or_else(|| c.include.clone())
                .unwrap_or_default(),
            exclude: cli
                .exclude
                .clone()
                .or_else(|| c.exclude.clone())
                .unwrap_or_default(),
            limits: Limits {
                max_file_size: cli.max_file_size.unwrap_or(limits.max_file_size),
                max_depth: cli.max_depth.unwrap_or(limits.max_depth),
            },
            skip_dirs: vec![],
            allow_empty: overrides.allow_empty,
            // Filled by [`pin_sources`]: fetching is not a matter of combining settings.
            sources: Vec::new(),
            // Sources configured and no input directory named: only the sources are read.
            sources_only: c.source.as_ref().is_some_and(|s| !s.is_empty())
                && cli.input.is_none()
                && c.input.is_none(),
            // `--jobs` is set with the sources ([`pin_sources`]'s caller).
            jobs: c.jobs,
            history: cli
                .history
                .or(c.history)
                .unwrap_or(crate::history::DEFAULT_LIMIT),
            history_reader: Some(crate::history::attach),
            // Checked when the file was parsed.
            implementation: c
                .implementation
                .as_ref()
                .and_then(|i| {
                    i.settings(file.path.as_deref().unwrap_or(Path::new(FILE_NAME)))
                        .ok()
                })
                .unwrap_or_default(),
            stability,
            idl_path: match &cli.idl_path {
                Some(paths) => paths.clone(),
                None => c
                    .idl_path
                    .iter()
                    .flatten()
                    .map(|p| file.resolve(p))
                    .collect(),
            },
        },
        site: crate::render::SiteOptions {
            title: cli
                .title
                .clone()
                .or_else(|| c.title.clone())
                .unwrap_or_else(|| default_title(cli.language.or(c.language).unwrap_or_default())),
            base_url: cli.base_url.clone().or_else(|| c.base_url.clone()),
            theme_dir: cli
                .theme
                .clone()
                .or_else(|| c.theme.as_deref().map(|p| file.resolve(p))),
            language: cli.language.or(c.language).unwrap_or_default(),
            show_host_data: c.show_host_data.unwrap_or(false),
            markdown_diagrams: c
                .markdown
                .as_ref()
                .and_then(|m| m.diagrams)
                .unwrap_or_default(),
            source_url: c.source_url.clone(),
        },
    }
}

#[cfg(test)]
mod precedence_tests {
    use super::*;

    fn loaded(text: &str) -> Loaded {
        Loaded {
            config: parse(text, Path::new("rtcdoc.toml")).unwrap(),
            dir: Some(PathBuf::from("/proj")),
            path: Some(PathBuf::from("/proj/rtcdoc.toml")),
        }
    }

    #[test]
    fn defaults_without_file_or_flags() {
        let o = build_options(&Loaded::default(), &Overrides::default());
        assert_eq!(o.input, PathBuf::from("."));
        assert_eq!(o.output, PathBuf::from("site"));
        assert_eq!(o.formats, vec![Format::Html]);
        assert!(!o.strict);
        assert_eq!(o.site.language, Lang::En);
        assert_eq!(o.load.limits, Limits::default());
    }

    #[test]
    fn file_values_apply_relative_to_the_file() {
        let f = loaded(
            "title = \"Lab\"\noutput = \"public\"\ninput = \"profiles\"\nformats = [\"json\", \"markdown\"]\nlanguage = \"ja\"\nexclude = [\"old/**\"]\nstrict = true\nmax-depth = 10\ntheme = \"t\"\n",
        );
        let o = build_options(&f, &Overrides::default());
        assert_eq!(o.site.title, "Lab");
        assert_eq!(o.output, PathBuf::from("/proj/public"));
        assert_eq!(o.input, PathBuf::from("/proj/profiles"));
        assert_eq!(o.formats, vec![Format::Json, Format::Markdown]);
        assert_eq!(o.site.language, Lang::Ja);
        assert_eq!(o.load.exclude, vec!["old/**".to_string()]);
        assert!(o.strict);
        assert_eq!(o.load.limits.max_depth, 10);
        assert_eq!(o.site.theme_dir, Some(PathBuf::from("/proj/t")));
        // Without `input`, the file's directory is the input.
        let o = build_options(&loaded(""), &Overrides::default());
        assert_eq!(o.input, PathBuf::from("/proj"));
        assert_eq!(o.output, PathBuf::from("/proj/site"));
    }

    #[test]
    fn flags_override_the_file() {
        let f = loaded("title = \"Lab\"\noutput = \"public\"\nformats = [\"json\"]\nlanguage = \"ja\"\nexclude = [\"old/**\"]\nmax-depth = 10\n");
        let cli = Overrides {
            settings: Config {
                title: Some("CLI".into()),
                output: Some(PathBuf::from("out")),
                formats: Some(vec![Format::Html]),
                language: Some(Lang::En),
                exclude: Some(vec!["x/**".into()]),
                max_depth: Some(5),
                ..Default::default()
            },
            ..Default::default()
        };
        let o = build_options(&f, &cli);
        assert_eq!(o.site.title, "CLI");
        assert_eq!(o.output, PathBuf::from("out"));
        assert_eq!(o.formats, vec![Format::Html]);
        assert_eq!(o.site.language, Lang::En);
        assert_eq!(o.load.exclude, vec!["x/**".to_string()]);
        assert_eq!(o.load.limits.max_depth, 5);
    }
}
