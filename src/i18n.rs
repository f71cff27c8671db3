//! UI language: every generated label (headings, table headers, diagram labels, search UI) in
//! English and Japanese. Renderers never hard-code label text; they ask [`Lang::t`].

use serde::{Deserialize, Serialize};

/// The language of generated labels (profile text is shown as written).
#[derive(
    Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize, clap::ValueEnum,
)]
#[serde(rename_all = "lowercase")]
pub enum Lang {
    #[default]
    En,
    Ja,
}

impl Lang {
    /// BCP 47 tag for `<html lang>` and friends.
    pub fn tag(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Ja => "ja",
        }
    }

    /// The label for `key`; `??` when it is unknown (so a missing label is visible rather than
    /// blank). Tests assert every key has both languages.
    pub fn t(self, key: &str) -> &'static str {
        match label_index(key) {
            Some(i) => self.at(i),
            None => {
                // A key that is no label is a bug of ours: tests fail on it; a release build
                // shows `??` rather than stop.
                debug_assert!(false, "no label `{key}`");
                "??"
            }
        }
    }

    /// `n` and the label `key`, or `key_one` where `n` is 1: `1 port pair`, `2 port pairs`.
    pub fn count(self, n: impl Into<u64>, key: &str) -> String {
        let n: u64 = n.into();
        let one = (n == 1)
            .then(|| label_index(&format!("{key}_one")))
            .flatten();
        let text = one.map_or_else(|| self.t(key), |i| self.at(i));
        format!("{n} {text}")
    }

    /// The text of label `i` of [`LABELS`] in this language.
    fn at(self, i: usize) -> &'static str {
        match self {
            Lang::En => LABELS[i].1,
            Lang::Ja => LABELS[i].2,
        }
    }

    /// All labels of this language as (key, text) pairs (for template contexts).
    pub fn labels(self) -> impl Iterator<Item = (&'static str, &'static str)> {
        LABELS.iter().map(move |(k, en, ja)| {
            (
                *k,
                match self {
                    Lang::En => *en,
                    Lang::Ja => *ja,
                },
            )
        })
    }
}

/// The position of `key` in [`LABELS`] (and in [`Lang::labels`]). A hash lookup: templates,
/// the component page writer and fact tables ask for labels hundreds of times per page.
pub fn label_index(key: &str) -> Option<usize> {
    static INDEX: std::sync::LazyLock<
        std::collections::HashMap<&'static str, usize, std::hash::BuildHasherDefault<EdgeHash>>,
    > = std::sync::LazyLock::new(|| {
        LABELS
            .iter()
            .enumerate()
            .map(|(i, (k, _, _))| (*k, i))
            .collect()
    });
    INDEX.get(key).copied()
}

/// A hash of a label key's length and its first and last eight bytes: the keys are short,
/// fixed and ours, and they differ there (checked by a test), so the hash need not read every
/// byte. SipHash, the default, guards against chosen keys and was a tenth of the page writer's
/// time; FNV-1a, one multiply per byte, cost about 5 M more instructions at 600 profiles.
#[derive(Default)]
struct EdgeHash(u64);

impl std::hash::Hasher for EdgeHash {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        let n = bytes.len();
        let word = |b: &[u8]| {
            let mut w = [0u8; 8];
            w[..b.len()].copy_from_slice(b);
            u64::from_le_bytes(w)
        };
        let head = word(&bytes[..n.min(8)]);
        let tail = word(&bytes[n.saturating_sub(8)..]);
        let mixed = (self.0.rotate_left(23) ^ head ^ (n as u64).rotate_left(56))
            .wrapping_mul(0x9e37_79b9_7f4a_7c15)
            ^ tail;
        self.0 = mixed.wrapping_mul(0xff51_afd7_ed55_8ccd) ^ (mixed >> 29);
    }
}

/// (key, English, Japanese), sorted by key (checked by a test).
pub const LABELS: &[(&str, &str, &str)] = &[
    ("abstract", "Abstract", "要約"),
    ("actions", "Lifecycle", "ライフサイクル"),
    ("activity_type", "Activity type", "アクティビティ型"),
    ("algorithm", "Algorithm", "アルゴリズム"),
    ("all_categories", "All categories", "すべてのカテゴリ"),
    ("all_codes", "All codes", "すべてのコード"),
    ("all_severities", "All severities", "すべての重大度"),
    ("all_sources", "All sources", "すべてのソース"),
    ("all_vendors", "All vendors", "すべてのベンダー"),
    ("argument", "Arguments", "引数"),
    (
        "backup_declares",
        "Declares",
        "記述内容",
    ),
    ("backup_file", "File", "ファイル"),
    ("backup_saved", "Saved", "保存日時"),
    (
        "backup_unreadable",
        "could not be read",
        "読み込めません",
    ),
    ("backups", "RTCBuilder backups", "RTCBuilder のバックアップ"),
    (
        "backups_intro",
        "Older versions of this profile that RTCBuilder kept beside it on each save (RTC.xml followed by the date). They are not documented as components.",
        "RTCBuilder が保存のたびにこのプロファイルの横に残した以前の版です（RTC.xml の後に保存日時が付いた名前）。コンポーネントとしては扱いません。",
    ),
    ("breadcrumbs", "Breadcrumbs", "パンくずリスト"),
    ("callback", "Callback", "コールバック"),
    ("catalogue", "Catalogue", "カタログ"),
    ("categories", "Categories", "カテゴリ"),
    ("category", "Category", "カテゴリ"),
    ("change_history", "History", "変更の履歴"),
    ("code", "Code", "コード"),
    ("comment", "Comment", "コメント"),
    ("component", "Component", "コンポーネント"),
    ("component_diagram", "Component diagram", "コンポーネント図"),
    ("component_kind", "Component kind", "コンポーネント種別"),
    ("component_type", "Component type", "コンポーネント型"),
    ("components", "Components", "コンポーネント"),
    ("condition", "Condition", "条件"),
    ("configuration", "Configuration parameters", "コンフィギュレーション"),
    ("connects_to", "Connects to", "接続先"),
    ("constraint", "Constraint", "制約"),
    ("constraint_and", " and ", " かつ "),
    ("constraint_any_case", " (any case)", " (大文字と小文字を区別しない)"),
    ("constraint_any_text", "any text", "任意の文字列"),
    ("constraint_escape", "escape", "エスケープ"),
    ("constraint_not_after", ")", ") でない"),
    ("constraint_not_before", "not (", "("),
    ("constraint_not_null", "not null", "null でない"),
    ("constraint_one_char", "one character", "任意の1文字"),
    ("constraint_one_of", "one of: ", "次のいずれか: "),
    ("constraint_or", " or ", " または "),
    ("consumers", "Consumers (in ports)", "利用者 (入力ポート)"),
    ("count", "Count", "件数"),
    ("cpu_other", "Other CPU", "その他のCPU"),
    ("cpus", "CPUs", "CPU"),
    ("creation_date", "Created", "作成日"),
    ("creator", "Creator", "作成者"),
    ("data_ports", "Data ports", "データポート"),
    ("data_type", "Data type", "データ型"),
    ("data_types", "Data types", "データ型"),
    ("dataflow", "Data flow", "データフロー"),
    ("dataflow_by_category", "Between categories", "カテゴリの間"),
    ("dataflow_by_vendor", "Between vendors", "ベンダーの間"),
    ("dataflow_flows", "flows", "件の流れ"),
    ("dataflow_from", "From", "送り元"),
    ("dataflow_groups", "groups", "個のグループ"),
    ("dataflow_intro", "Which components can feed which: an out-port of a data type can feed every in-port of the same type. Each flow between two groups counts the out-port/in-port pairs behind it (a component's out-port to its own in-port is not counted); a flow from a group to itself stays inside the group.", "どのコンポーネントがどのコンポーネントにデータを送れるか: あるデータ型の出力ポートは、同じ型のすべての入力ポートに送れます。2つのグループの間の流れには、その元になる出力ポートと入力ポートの組の数を示します(コンポーネント自身の出力ポートから入力ポートへの組は数えません)。グループから同じグループへの流れはグループ内の流れです。"),
    ("dataflow_none", "No data flows: no out-port and in-port of different components carry the same data type.", "データの流れはありません: 異なるコンポーネントの出力ポートと入力ポートで同じデータ型を運ぶものがありません。"),
    ("dataflow_not_drawn", "The drawing shows the groups with the most port pairs and their heaviest flows; the table lists every flow. Not drawn", "図には、ポートの組の多いグループとその主な流れだけを描いています。すべての流れは表にあります。図にないもの"),
    ("dataflow_pair_count", "port pairs", "組のポート"),
    ("dataflow_pair_count_one", "port pair", "組のポート"),
    ("dataflow_pairs", "Port pairs", "ポートの組"),
    ("dataflow_to", "To", "送り先"),
    ("dataflow_type", "Dataflow type", "データフロー型"),
    ("dataname", "Data name", "データ名"),
    ("default_value", "Default", "デフォルト値"),
    ("description", "Description", "概要"),
    ("diag_files", "Files", "ファイル"),
    ("diag_intro", "Errors and warnings by file, then the infos summarised by code. Every finding: rtcdoc check.", "ファイルごとのエラーと警告、続いてコード別の情報の要約。すべての指摘は rtcdoc check で。"),
    ("diag_page", "page", "ページ"),
    ("diag_pages", "Pages of the diagnostics (files with errors first)", "診断のページ (エラーのあるファイルが先)"),
    ("diagnostics", "Diagnostics", "診断"),
    ("direction", "Direction", "方向"),
    ("doc_type", "Type description", "型の説明"),
    ("document", "Documentation", "ドキュメント"),
    ("ec_events", "Execution context events", "実行コンテキストのイベント"),
    (
        "empty_facets",
        "None: the catalogue documents no component profile.",
        "ありません。カタログにコンポーネントのプロファイルがありません。",
    ),
    (
        "empty_interfaces",
        "None: no service port of the catalogue names an interface type.",
        "ありません。カタログのサービスポートはインターフェース型を示していません。",
    ),
    (
        "empty_types",
        "None: no data port of the catalogue names a data type.",
        "ありません。カタログのデータポートはデータ型を示していません。",
    ),
    ("errors", "errors", "エラー"),
    ("event", "Event", "イベント"),
    ("event_target", "Target state", "遷移先"),
    ("events", "Events", "イベント"),
    ("example", "Example", "例"),
    ("exception", "Exceptions", "例外"),
    ("execution_rate", "Execution rate", "実行周期"),
    ("execution_type", "Execution type", "実行型"),
    ("extra", "Extra properties", "追加プロパティ"),
    ("extra_kind", "Kind", "種別"),
    ("extra_path", "Where", "場所"),
    ("facet_variants", "Also written", "別の表記"),
    ("fact_abstract", "Abstract", "要約"),
    ("fact_basic_info", "Basic information", "基本情報"),
    ("fact_callback", "Callback", "コールバック"),
    ("fact_catalogue", "Catalogue", "カタログ"),
    ("fact_comment", "Comment", "コメント"),
    ("fact_cpu_other", "Other CPU", "その他のCPU"),
    ("fact_cpus", "CPUs", "CPU"),
    ("fact_dataflow_type", "Dataflow type", "データフロー型"),
    ("fact_dataname", "Data name", "データ名"),
    ("fact_details", "Details", "詳細"),
    ("fact_doc_argument", "Arguments", "引数"),
    ("fact_doc_constraint", "Documented constraint", "制約 (ドキュメント)"),
    ("fact_doc_default", "Documented default", "デフォルト値 (ドキュメント)"),
    ("fact_doc_exception", "Exceptions", "例外"),
    ("fact_doc_return", "Return value", "戻り値"),
    ("fact_doc_type", "Documented type", "データ型 (ドキュメント)"),
    ("fact_doc_unit", "Documented unit", "単位 (ドキュメント)"),
    ("fact_document", "Document profile", "ドキュメント"),
    ("fact_event", "Event", "イベント"),
    ("fact_field", "Field", "項目"),
    ("fact_hardware_profile", "Hardware profile", "ハードウェアプロファイル"),
    ("fact_id", "Identifier", "識別子"),
    ("fact_idl_file", "IDL file", "IDLファイル"),
    ("fact_idl_files", "IDL files", "IDLファイル"),
    ("fact_if_description", "Interface description", "インターフェース概要"),
    ("fact_instance_name", "Instance name", "インスタンス名"),
    ("fact_interface_type", "Interface type", "インターフェース型"),
    ("fact_lang_version", "Language version", "言語バージョン"),
    ("fact_library", "Library", "ライブラリ"),
    ("fact_more", "more", "件 (続きは型のページ)"),
    ("fact_none", "none", "なし"),
    ("fact_number", "Number", "数"),
    ("fact_occurrence", "Occurrence", "発生頻度"),
    ("fact_operation", "Operation", "操作"),
    ("fact_os", "OS", "OS"),
    ("fact_os_versions", "OS versions", "OSバージョン"),
    ("fact_other", "Other", "その他"),
    ("fact_others", "Other ports", "その他のポート"),
    ("fact_path", "IDL search path", "IDLパス"),
    (
        "fact_placeholder",
        "RTCBuilder's placeholder, not filled in",
        "RTCBuilder の初期値のまま（未記入）",
    ),
    ("fact_port", "Port", "ポート"),
    ("fact_position", "Position", "位置"),
    ("fact_profile_version", "Profile format version", "プロファイル形式バージョン"),
    ("fact_range", "Range", "範囲"),
    ("fact_rtc_type", "RTC type", "RTC型"),
    ("fact_save_project", "Saved project", "保存プロジェクト"),
    ("fact_semantics", "Semantics", "意味"),
    ("fact_spellings", "Spellings", "表記"),
    ("fact_step", "Step", "刻み幅"),
    ("fact_subscription_type", "Subscription type", "サブスクリプション型"),
    ("fact_target", "Target environment", "ターゲット環境"),
    ("fact_trans_methods", "Transport methods", "転送方式"),
    ("fact_uncategorized", "(no category)", "(カテゴリなし)"),
    ("fact_used_by", "Used by", "利用コンポーネント"),
    ("fact_value", "Value", "値"),
    ("fact_variable_name", "Variable name", "変数名"),
    ("fact_w_checkbox", "check boxes", "チェックボックス"),
    ("fact_w_ordered_list", "ordered list", "順序付きリスト"),
    ("fact_w_radio", "radio buttons", "ラジオボタン"),
    ("fact_w_slider", "slider", "スライダー"),
    ("fact_w_spin", "spin box", "スピンボックス"),
    ("fact_w_text", "text box", "テキストボックス"),
    ("fact_widget", "Widget", "ウィジェット"),
    ("feed_title", "Changes (Atom feed)", "変更 (Atom フィード)"),
    ("file", "File", "ファイル"),
    ("filter", "Filter", "絞り込み"),
    ("filter_count", "{n} of {total} components shown", "{total} 件中 {n} 件を表示"),
    (
        "filter_none",
        "No component matches the filter. The search box at the top reads descriptions too.",
        "条件に合うコンポーネントはありません。上の検索ボックスでは概要の文も検索できます。",
    ),
    ("filter_placeholder", "Filter by name…", "名前で絞り込み…"),
    ("fsm_actions", "FSM and mode callbacks", "FSM・モードのコールバック"),
    ("hardware_profile", "Hardware profile", "ハードウェアプロファイル"),
    ("hint", "Hint", "ヒント"),
    ("history_all", "All versions", "すべての版"),
    ("history_author", "Author", "作成者"),
    ("history_changes", "Changes", "変更"),
    ("history_commit", "Commit", "コミット"),
    ("history_current_file", "current file", "現在のファイル"),
    ("history_current_files", "Current files", "現在のファイル"),
    ("history_date", "Date", "日付"),
    ("history_first", "first version in the history", "履歴の最初の版"),
    ("history_folded", "{n} versions without changes to the specification", "仕様に変更のない版 {n} 件"),
    ("history_folded_one", "1 version without changes to the specification", "仕様に変更のない版 1 件"),
    ("history_full", "The whole history, with every change", "すべての変更を含む履歴全体"),
    ("history_idl_types", "Types defined in this file", "このファイルで定義する型"),
    ("history_intro", "The latest versions of this profile (the commits that changed it, RTCBuilder's backups), newest first, each with what changed from the version before as rtcdoc diff classifies it.", "このプロファイルの最近の版（変更したコミット、RTCBuilder のバックアップ）を新しい順に示します。各版には、一つ前の版からの変更を rtcdoc diff と同じ分類で示します。"),
    ("history_intro_idl", "The latest versions of the IDL file defining this type (the commits that changed it), newest first, each with what changed in its types from the version before as rtcdoc diff classifies it.", "この型を定義する IDL ファイルの最近の版（変更したコミット）を新しい順に示します。各版には、一つ前の版からの型の変更を rtcdoc diff と同じ分類で示します。"),
    ("history_intro_system", "The latest versions of this RT System profile (the commits that changed it), newest first, each with what changed from the version before as rtcdoc diff classifies it.", "この RT システムプロファイルの最近の版（変更したコミット）を新しい順に示します。各版には、一つ前の版からの変更を rtcdoc diff と同じ分類で示します。"),
    ("history_moved", "moved from {file}", "{file} から移動"),
    ("history_n_breaking", "{n} breaking", "破壊的変更 {n}"),
    ("history_n_breaking_one", "1 breaking", "破壊的変更 1"),
    ("history_n_info", "{n} info", "情報 {n}"),
    ("history_n_info_one", "1 info", "情報 1"),
    ("history_n_warning", "{n} warnings", "警告 {n}"),
    ("history_n_warning_one", "1 warning", "警告 1"),
    ("history_no_date", "Without a date", "日付なし"),
    ("history_no_spec_change", "no change to the specification", "仕様の変更なし"),
    ("history_older", "{n} older versions are on the history page and in catalog.json.", "これより古い {n} 版は履歴のページと catalog.json にあります。"),
    ("history_page_intro", "Every version of this profile read (the commits that changed it, RTCBuilder's backups), newest first, each with every change from the version before as rtcdoc diff classifies it. Versions that changed nothing of the specification are folded.", "読み込んだこのプロファイルのすべての版（変更したコミット、RTCBuilder のバックアップ）を新しい順に示します。各版には、一つ前の版からのすべての変更を rtcdoc diff と同じ分類で示します。仕様に変更のない版はまとめて示します。"),
    ("history_page_intro_idl", "Every version of this IDL file read (the commits that changed it), newest first, each with every change to its types from the version before as rtcdoc diff classifies it, linked to the page of the type where it has one. Versions that changed no type are folded.", "読み込んだこの IDL ファイルのすべての版（変更したコミット）を新しい順に示します。各版には、一つ前の版からの型のすべての変更を rtcdoc diff と同じ分類で示し、ページのある型はそのページにリンクします。型に変更のない版はまとめて示します。"),
    ("history_page_intro_system", "Every version of this RT System profile read (the commits that changed it), newest first, each with every change from the version before as rtcdoc diff classifies it. Versions that changed nothing of the system are folded.", "読み込んだこの RT システムプロファイルのすべての版（変更したコミット）を新しい順に示します。各版には、一つ前の版からのすべての変更を rtcdoc diff と同じ分類で示します。システムに変更のない版はまとめて示します。"),
    ("history_page_title", "History of {name}", "{name} の変更の履歴"),
    ("history_reach", "Reaches {n} other components: {list}", "ほかのコンポーネント {n} 件に及びます：{list}"),
    ("history_reach_consumer", "consumer", "利用者"),
    ("history_reach_one", "Reaches 1 other component: {list}", "ほかのコンポーネント 1 件に及びます：{list}"),
    ("history_reach_other", "other use", "その他の利用"),
    ("history_reach_producer", "producer", "提供者"),
    ("history_reach_provider", "provider", "提供側"),
    ("history_reach_requirer", "requirer", "要求側"),
    ("history_release", "release", "リリース"),
    ("history_release_note", "A release: the version string changed.", "リリース：バージョン文字列が変わりました。"),
    ("history_row_more", "{n} more changes on the history page", "ほか {n} 件の変更は履歴のページにあります"),
    ("history_row_more_one", "1 more change on the history page", "ほか 1 件の変更は履歴のページにあります"),
    ("history_separator", ", ", "、"),
    ("history_subject", "Subject", "件名"),
    ("history_unreadable", "could not be read", "読み込めません"),
    ("history_version", "Version", "バージョン"),
    ("history_working_copy", "working copy (not committed)", "作業コピー（未コミット）"),
    ("id_label", "Id", "ID"),
    ("idl_aliases", "Aliases", "別名の型"),
    ("idl_attributes", "Attributes", "属性"),
    ("idl_bases", "Base interfaces", "基底インターフェース"),
    ("idl_cases", "Cases", "ケース"),
    ("idl_contained_in", "Contained in", "この型を含む型"),
    ("idl_defined_in", "Defined in", "定義"),
    ("idl_definition", "Definition", "定義"),
    ("idl_field", "Field", "フィールド"),
    ("idl_file", "IDL file", "IDLファイル"),
    ("idl_files", "IDL files", "IDLファイル"),
    ("idl_inherited_from", "Inherited from", "継承元"),
    ("idl_member", "Operation or attribute", "オペレーション・属性"),
    (
        "idl_no_definition",
        "Defined in no IDL file read, so its definition is not shown: add the IDL file below the input, pass --idl-path DIR, or let rtcdoc init find an OpenRTM installation.",
        "読み込んだ IDL ファイルのどれにも定義がないため、定義を表示できません。入力ディレクトリの下に IDL ファイルを置くか、--idl-path DIR を指定するか、rtcdoc init で OpenRTM のインストールを探してください。",
    ),
    ("idl_note", "Note", "注記"),
    ("idl_oneway", "oneway", "oneway"),
    ("idl_operations", "Operations", "オペレーション"),
    ("idl_params", "Parameters", "引数"),
    ("idl_path", "IDL path", "IDLパス"),
    ("idl_raises", "Raises", "例外"),
    ("idl_readonly", "read-only", "読み取り専用"),
    ("idl_returns", "Returns", "戻り値"),
    ("idl_see", "See also", "参照"),
    ("idl_switch", "Switch type", "判別子の型"),
    ("idl_use", "Use", "使われ方"),
    ("idl_use_attribute", "attribute", "属性"),
    ("idl_use_parameter", "parameter", "引数"),
    ("idl_use_raises", "raised", "例外"),
    ("idl_use_result", "result", "戻り値"),
    ("idl_used_by", "Used by interfaces", "この型を使うインターフェース"),
    ("idl_values", "Values", "値"),
    ("if_description", "Interface description", "インターフェース概要"),
    ("impl_absent", "(none)", "（なし）"),
    ("impl_code_says", "Code says", "コード"),
    ("impl_differences", "{n} differences from the specification", "仕様との相違 {n} 件"),
    ("impl_element", "Element", "要素"),
    ("impl_files", "Files read", "読んだファイル"),
    ("impl_filter_all", "any", "すべて"),
    ("impl_filter_drift", "differs from the profile", "プロファイルと相違あり"),
    ("impl_filter_none", "no code read", "コードなし"),
    ("impl_filter_ok", "matches the profile", "プロファイルと一致"),
    (
        "impl_filter_recovered",
        "no profile: recovered from the code",
        "プロファイルなし（コードから復元）",
    ),
    (
        "impl_intro",
        "What the component's code registers, read from the files beside its profile and compared with it.",
        "プロファイルの横にあるソースコードが登録しているもの（ポート・パラメータ・コールバック・spec 配列）を読み、プロファイルと比べた結果です。",
    ),
    ("impl_matches", "matches the specification", "仕様と一致"),
    ("impl_profile_says", "Profile says", "プロファイル"),
    ("impl_recovered", "recovered from the source", "ソースコードから復元"),
    (
        "impl_recovered_intro",
        "This component has no profile (RTC.xml): it is documented from its code — the spec array, the ports, service ports and parameters it registers, the callbacks it implements. The command rtcdoc extract writes the RTC.xml this describes.",
        "このコンポーネントにはプロファイル（RTC.xml）がありません。コード（spec 配列、登録しているポート・サービスポート・パラメータ、実装しているコールバック）から文書化しています。rtcdoc extract コマンドでこの内容の RTC.xml を書き出せます。",
    ),
    (
        "impl_recovered_note",
        "No profile: documented from the source code",
        "プロファイルなし: ソースコードから文書化",
    ),
    (
        "impl_unread",
        "Not read from the code (left empty, not guessed):",
        "コードから読み取れなかった値（推測せず空のまま）:",
    ),
    (
        "impl_unverified",
        "Could not be verified (built at run time, a macro, a base class):",
        "静的には確認できなかったもの（実行時に作る名前・マクロ・基底クラス）:",
    ),
    ("impl_where", "Where", "場所"),
    ("implementation", "Implementation", "実装"),
    ("implemented", "Implemented", "実装"),
    ("in", "In", "入力"),
    ("infos", "infos", "情報"),
    ("infos_by_code", "Infos by code", "コード別の情報"),
    ("inout", "Input and output", "入出力"),
    ("instance", "Instance", "インスタンス"),
    ("instance_name", "Instance name", "インスタンス名"),
    ("instances", "Instances", "インスタンス"),
    ("interface", "Interface", "インターフェース"),
    ("interface_no_components", "No component of this catalogue provides or requires it: it is defined in IDL only.", "このカタログには、これを提供または要求するコンポーネントがありません(IDL でのみ定義されています)。"),
    ("interface_type", "Interface type", "インターフェース型"),
    ("interfaces", "Service interfaces", "サービスインターフェース"),
    ("interfaces_intro", "Service interface types used by the service ports of the catalogue or defined in its IDL files, with the components that provide and require them.", "カタログのサービスポートで使われる、または IDL ファイルで定義されたインターフェース型と、それを提供・要求するコンポーネントです。"),
    ("key", "Key", "キー"),
    ("lang_version", "Language version", "言語バージョン"),
    ("language", "Language", "言語"),
    ("legend_implemented", "implemented callback", "実装済みコールバック"),
    ("legend_not_implemented", "callback not implemented", "未実装のコールバック"),
    ("libraries", "Libraries", "ライブラリ"),
    ("license", "License", "ライセンス"),
    ("lifecycle_diagram", "Lifecycle state diagram", "ライフサイクル状態遷移図"),
    ("main_nav", "Site", "サイト"),
    ("manual", "System manual", "システムマニュアル"),
    ("manual_appendix", "Appendix: data types and interfaces", "付録: データ型とインターフェース"),
    ("manual_contents", "Contents", "目次"),
    ("manual_list", "System manuals", "システムマニュアル一覧"),
    ("manual_no_definition", "Its IDL definition was not available when this manual was made.", "この手引きを作ったとき、その IDL の定義は読み込めませんでした。"),
    ("manual_no_systems", "The catalogue has no RT System.", "カタログに RT システムはありません。"),
    ("manual_runs_as", "Runs in this system as", "このシステムでのインスタンス"),
    ("max_instances", "Max instances", "最大インスタンス数"),
    ("message", "Message", "メッセージ"),
    ("more_on_interface_page", "see all on the interface page", "すべてはインターフェースのページへ"),
    ("more_on_type_page", "see all on the type page", "すべては型のページへ"),
    ("name", "Name", "名前"),
    ("nb_fed_by", "fed by", "入力元"),
    ("nb_feeds", "feeds", "出力先"),
    ("nb_more", "more", "件ほか"),
    ("nb_more_listed", "see the list below", "下の一覧を参照"),
    ("nb_port_count", "ports", "個のポート"),
    ("nb_port_count_one", "port", "個のポート"),
    ("nb_used_by", "used by", "利用元"),
    ("nb_uses", "uses", "利用先"),
    ("neighbourhood", "Neighbourhood", "接続できるコンポーネント"),
    ("neighbourhood_drawing", "In the drawing, the components that only feed it (or only use its provided interfaces) are on the left; those it feeds (or whose interfaces it uses), and those that both feed it and are fed by it, on the right. Each neighbour has one edge per direction, labelled with its number of port pairs; the 8 with the most port pairs are drawn and the others counted in a \"+N more\" box.", "図では、データを送ってくるだけのもの(提供インターフェースを利用するだけのもの)を左に、データを送る先(利用するインターフェースの提供元)と、送受の両方を行うものを右に描きます。隣接するコンポーネントごとに向きごとに 1 本の線を引き、ポートの組数を添えます。組数の多い 8 件までを描き、残りは「+N 件ほか」の箱に数えます。"),
    ("neighbourhood_intro", "The other components of this catalogue that can connect to each port, one hop. At most 5 are named per port; the rest are counted and listed on the type or interface page.", "各ポートに直接接続できる、このカタログのほかのコンポーネントです。ポートごとに最大 5 件を挙げ、残りは件数を示して型またはインターフェースのページで一覧します。"),
    ("neighbourhood_none", "No other component in this catalogue connects to it.", "このカタログには、これと接続できるほかのコンポーネントがありません。"),
    ("neighbourhood_of", "Neighbourhood of", "接続できるコンポーネント:"),
    ("no", "no", "いいえ"),
    ("no_category", "(no category)", "(カテゴリなし)"),
    ("no_results", "No results", "該当なし"),
    ("no_vendor", "(no vendor)", "(ベンダーなし)"),
    ("not_found_text", "The page you asked for does not exist. Try the catalogue or the search.", "お探しのページは存在しません。カタログか検索をお試しください。"),
    ("not_found_title", "Page not found", "ページが見つかりません"),
    ("not_implemented", "not implemented", "未実装"),
    ("not_provided", "Required but provided by no component in this catalogue", "このカタログのどのコンポーネントも提供していない"),
    ("number", "Number", "数"),
    ("occurrence", "Occurrence", "発生頻度"),
    ("operation", "Operation", "操作"),
    ("os", "OS", "OS"),
    ("os_versions", "OS versions", "OSバージョン"),
    ("other", "Other", "その他"),
    ("others", "Other ports", "その他のポート"),
    ("out", "Out", "出力"),
    ("parameters", "System parameters", "システムパラメータ"),
    ("port", "Port", "ポート"),
    ("position", "Position", "位置"),
    ("post_condition", "Post-condition", "事後条件"),
    ("pre_condition", "Pre-condition", "事前条件"),
    ("producers", "Producers (out ports)", "提供者 (出力ポート)"),
    ("profile_version", "Profile format version", "プロファイル形式バージョン"),
    ("prop_container_lib", "Container library", "コンテナライブラリ"),
    ("prop_fsm", "Finite state machine (FSM)", "有限状態機械 (FSM)"),
    ("prop_fsm_type", "FSM type", "FSM の種類"),
    ("prop_iso", "ISO 22166-202", "ISO 22166-202"),
    ("properties", "Properties", "プロパティ"),
    ("provided", "Provided", "提供"),
    ("providers", "Providers", "提供コンポーネント"),
    ("range", "Range", "範囲"),
    ("readme", "README", "README"),
    ("reference", "Reference", "参考文献"),
    ("required", "Required", "要求"),
    ("requirers", "Consumers (required)", "利用コンポーネント (要求)"),
    ("results", "Results", "結果"),
    ("return", "Return value", "戻り値"),
    ("rtc_type", "RTC type", "RTC型"),
    ("save_project", "Project", "プロジェクト"),
    ("search", "Search", "検索"),
    ("search_help", "Type to search. ↓/↑ move through the results, Enter opens one, / jumps to the search box. Ports by type: in:TYPE, out:TYPE, provides:TYPE, requires:TYPE; what can feed an in-port: feeds:COMPONENT.PORT.", "入力すると検索します。↓/↑で結果を移動、Enterで開く、/で検索欄へ。型でポートを探す: in:型、out:型、provides:型、requires:型。入力ポートにつなげる出力ポート: feeds:コンポーネント.ポート。"),
    ("search_placeholder", "Search components, ports, types…", "コンポーネント・ポート・型を検索…"),
    ("semantics", "Semantics", "意味"),
    ("service_ports", "Service ports", "サービスポート"),
    ("severity", "Severity", "重大度"),
    ("severity_breaking", "breaking", "破壊的"),
    ("severity_error", "error", "エラー"),
    ("severity_info", "info", "情報"),
    ("severity_warning", "warning", "警告"),
    ("show_in_category", "Jump to a category", "カテゴリへ移動"),
    ("since", "since {v}", "{v} から"),
    ("since_title", "Added in {v} (from the history)", "{v} で追加（履歴より）"),
    ("skip", "Skip to content", "本文へ移動"),
    ("source", "Source", "ソース"),
    ("source_folder", "Folder", "フォルダ"),
    ("spellings", "Spellings", "表記"),
    ("stability_deprecated", "Deprecated", "非推奨"),
    ("stability_experimental", "Experimental", "実験的"),
    ("stability_since", "{status} since {since}", "{since} から{status}"),
    ("stability_stable", "Stable", "安定"),
    ("stability_use", "use {}", "代わりに {} を使用"),
    ("state_active", "Active", "Active (活性)"),
    ("state_created", "Created", "Created (生成)"),
    ("state_error", "Error", "Error (エラー)"),
    ("state_finalized", "Finalized", "Finalized (終了)"),
    ("state_inactive", "Inactive", "Inactive (非活性)"),
    ("step", "Step", "ステップ"),
    ("subscription_type", "Subscription type", "サブスクリプション型"),
    ("sys_abstract", "Abstract", "概要"),
    ("sys_active_set", "Active configuration set", "アクティブなコンフィギュレーションセット"),
    ("sys_after", "after", "次の後に"),
    ("sys_all_values", "Every value of the file", "ファイルのすべての値"),
    ("sys_carried_by", "System connectors carrying this type", "この型を運ぶシステムのコネクタ"),
    ("sys_component_default", "Component default", "コンポーネントのデフォルト値"),
    ("sys_component_id", "Component id", "コンポーネントID"),
    ("sys_composite", "Composite type", "複合型"),
    ("sys_condition", "Condition", "条件"),
    ("sys_configuration", "Configuration used", "使用するコンフィギュレーション"),
    ("sys_connector", "Connector", "コネクタ"),
    ("sys_connector_id", "Connector id", "コネクタID"),
    ("sys_context", "Execution context", "実行コンテキスト"),
    ("sys_contexts", "Execution contexts", "実行コンテキスト"),
    ("sys_data_connectors", "data connectors", "データポートコネクタ"),
    ("sys_data_connectors_h", "Data port connectors", "データポートコネクタ"),
    ("sys_data_connectors_one", "data connector", "データポートコネクタ"),
    ("sys_dataflow", "Dataflow", "データフロー型"),
    ("sys_drift", "version drift: the catalogue has", "バージョンの相違: カタログの版は"),
    ("sys_format_version", "Profile format version", "プロファイル形式のバージョン"),
    ("sys_groups", "Groups", "グループ"),
    ("sys_host_hidden", "host values hidden (host names, IORs, endpoints, naming paths); set show-host-data = true in rtcdoc.toml to publish them", "個のホスト情報を非表示 (ホスト名、IOR、エンドポイント、ネーミングパス)。公開するには rtcdoc.toml で show-host-data = true と設定してください"),
    ("sys_id", "System id", "システムID"),
    ("sys_in_port", "in-port", "入力ポート"),
    ("sys_instance_count", "instances", "インスタンス"),
    ("sys_instance_count_one", "instance", "インスタンス"),
    ("sys_interface_type", "Interface type", "インターフェース型"),
    ("sys_legend_composite", "double outline: composite component", "二重の枠: 複合コンポーネント"),
    ("sys_legend_member", "dashed outline: member of a composite", "破線の枠: 複合コンポーネントのメンバー"),
    ("sys_legend_other_port", "hollow square: a port of unknown kind", "白抜きの四角: 種類の分からないポート"),
    ("sys_legend_unknown_port", "dotted square: a port not in its component's profile (or its instance's port list)", "点線の四角: コンポーネントのプロファイル(またはインスタンスのポート一覧)にないポート"),
    ("sys_member_of", "member of", "所属する複合コンポーネント:"),
    ("sys_members", "Members", "メンバー"),
    ("sys_no_end", "an end is missing", "端が書かれていない"),
    ("sys_no_instance", "the system has no instance", "システムにないインスタンス:"),
    ("sys_no_port", "a port is missing", "ポートが見つからない"),
    ("sys_not_drawn", "Not drawn", "描かれていないコネクタ"),
    ("sys_not_in_catalogue", "not in the catalogue", "カタログにない"),
    ("sys_open_drawing", "Open the drawing on its own", "図だけを開く"),
    ("sys_orders", "Orders", "実行順序"),
    ("sys_out_port", "out-port", "出力ポート"),
    ("sys_path_uri", "Naming path", "ネーミングパス"),
    ("sys_port_not_in_profile", "not in the component's profile", "コンポーネントのプロファイルにない"),
    ("sys_port_not_listed", "not among the instance's ports in the system file", "システムファイルのインスタンスのポートにない"),
    ("sys_pseudo", "editor data", "エディタのデータ"),
    ("sys_push_interval", "Push interval", "プッシュ間隔"),
    ("sys_required", "Required", "必須"),
    ("sys_saved_as", "saved in the file as", "ファイル上の向き"),
    ("sys_sequence", "Sequence", "順番"),
    ("sys_service_connectors", "service connectors", "サービスポートコネクタ"),
    ("sys_service_connectors_h", "Service port connectors", "サービスポートコネクタ"),
    ("sys_service_connectors_one", "service connector", "サービスポートコネクタ"),
    ("sys_service_port", "service port", "サービスポート"),
    ("sys_set", "Configuration set", "コンフィギュレーションセット"),
    ("sys_source", "Source", "送信元"),
    ("sys_subscription", "Subscription", "サブスクリプション型"),
    ("sys_subsystems", "Sub-systems", "サブシステム"),
    ("sys_target", "Target", "送信先"),
    ("sys_timeout", "timeout", "タイムアウト"),
    ("sys_trans_method", "Transport", "転送方式"),
    ("sys_undeclared", "the component declares no such parameter", "コンポーネントにこのパラメータはない"),
    ("sys_used_by", "Used in systems", "使用するシステム"),
    ("sys_version_drift", "Version drift", "バージョンの相違"),
    ("sys_wait", "wait", "待機"),
    ("sys_wiring", "Wiring of", "配線:"),
    ("system", "RT System", "RTシステム"),
    ("systems", "Systems", "システム"),
    ("systems_intro", "RT System profiles: which component instances a system runs, how their ports are connected and which configuration each uses.", "RTシステムプロファイル: システムが動かすコンポーネントのインスタンス、ポートの接続、各インスタンスのコンフィギュレーション。"),
    ("targets", "Target environments", "ターゲット環境"),
    ("trans_methods", "Transport methods", "通信方式"),
    ("type", "Type", "型"),
    ("types_intro", "Data types carried by the data ports of the catalogue, with the components that produce and consume them.", "カタログのデータポートが扱うデータ型と、それを出力・入力するコンポーネントです。"),
    ("unit", "Unit", "単位"),
    ("unprovided", "not provided", "未提供"),
    ("update_date", "Updated", "更新日"),
    ("value", "Value", "値"),
    ("variable_name", "Variable name", "変数名"),
    ("vendor", "Vendor", "ベンダー"),
    ("vendors", "Vendors", "ベンダー"),
    ("version", "Version", "バージョン"),
    ("version_up_logs", "Version history", "更新履歴"),
    ("warnings", "warnings", "警告"),
    ("whats_new", "What's new", "新着の変更"),
    ("whats_new_intro", "Every change in the histories of the components, RT Systems and IDL files, newest first, grouped by day: what changed, in which version and commit, and how rtcdoc diff classifies it.", "コンポーネント、RT システム、IDL ファイルの履歴にあるすべての変更を新しい順に日付ごとに示します。何がどの版・コミットで変わったかを、rtcdoc diff による分類とともに示します。"),
    ("whats_new_more", "{n} older changes are on the history pages.", "これより古い {n} 件の変更は各履歴ページにあります。"),
    ("whats_new_none", "No version in the histories changed the specification yet.", "履歴のどの版も、まだ仕様を変更していません。"),
    ("whats_new_subject", "Component, RT System or IDL file", "コンポーネント・RTシステム・IDLファイル"),
    ("widget", "Widget", "ウィジェット"),
    ("yes", "yes", "はい"),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_are_sorted_unique_and_complete() {
        for w in LABELS.windows(2) {
            assert!(w[0].0 < w[1].0, "labels out of order at {}", w[1].0);
        }
        for (k, en, ja) in LABELS {
            assert!(
                !en.is_empty() && !ja.is_empty(),
                "label {k} lacks a language"
            );
        }
        assert_eq!(Lang::Ja.t("data_ports"), "データポート");
        assert_eq!(Lang::En.t("data_ports"), "Data ports");
    }

    /// A key that is no label stops a test (in a release build it shows as `??`).
    #[test]
    #[cfg(debug_assertions)]
    #[should_panic(expected = "no label `no-such-key`")]
    fn an_unknown_label_key_fails_a_test() {
        Lang::En.t("no-such-key");
    }

    /// Every label a built-in template names (`t.key`) is one.
    #[test]
    fn every_label_a_template_names_exists() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/themes/default");
        let mut seen = 0;
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().and_then(|e| e.to_str()) != Some("html") {
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            let bytes = text.as_bytes();
            for (at, _) in text.match_indices("t.") {
                let before = at.checked_sub(1).map(|i| bytes[i]);
                if before.is_some_and(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'.') {
                    continue;
                }
                let key: String = text[at + 2..]
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                if key.is_empty() || !key.starts_with(|c: char| c.is_ascii_lowercase()) {
                    continue;
                }
                seen += 1;
                assert!(
                    label_index(&key).is_some(),
                    "{}: t.{key} is no label",
                    path.display()
                );
            }
        }
        assert!(seen > 100, "{seen}");
    }

    /// The label keys hash apart, so a lookup compares one key at most.
    #[test]
    fn label_keys_hash_apart() {
        use std::hash::BuildHasher as _;
        let h = std::hash::BuildHasherDefault::<EdgeHash>::default();
        let mut seen = std::collections::HashMap::new();
        for (k, _, _) in LABELS {
            if let Some(other) = seen.insert(h.hash_one(k), k) {
                panic!("labels {other} and {k} have the same hash");
            }
        }
    }

    #[test]
    fn every_label_is_found_at_its_place() {
        let linear = |key: &str| LABELS.iter().position(|(k, _, _)| *k == key);
        for (i, (k, _, _)) in LABELS.iter().enumerate() {
            assert_eq!(label_index(k), Some(i), "{k}");
            // Near misses are found exactly when they are keys themselves.
            for near in [
                format!("{k}_"),
                k[..k.len() - 1].to_string(),
                k.to_uppercase(),
            ] {
                assert_eq!(label_index(&near), linear(&near), "{near}");
            }
        }
        assert_eq!(label_index(""), None);
    }

    #[test]
    fn a_count_of_one_takes_the_singular_label() {
        assert_eq!(
            Lang::En.count(1u64, "sys_data_connectors"),
            "1 data connector"
        );
        assert_eq!(
            Lang::En.count(3u64, "sys_data_connectors"),
            "3 data connectors"
        );
        assert_eq!(Lang::En.count(0u64, "sys_instance_count"), "0 instances");
        assert_eq!(Lang::En.count(1u64, "dataflow_pair_count"), "1 port pair");
        assert_eq!(Lang::Ja.count(1u64, "sys_instance_count"), "1 インスタンス");
    }
}
