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

    /// The label for `key`; the key itself when it is unknown (so a missing label is visible
    /// rather than blank). Tests assert every key has both languages.
    pub fn t(self, key: &str) -> &'static str {
        match LABELS.binary_search_by(|(k, _, _)| k.cmp(&key)) {
            Ok(i) => match self {
                Lang::En => LABELS[i].1,
                Lang::Ja => LABELS[i].2,
            },
            Err(_) => "??",
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

/// (key, English, Japanese), sorted by key (checked by a test).
pub const LABELS: &[(&str, &str, &str)] = &[
    ("actions", "Lifecycle", "ライフサイクル"),
    ("activity_type", "Activity type", "アクティビティ型"),
    ("algorithm", "Algorithm", "アルゴリズム"),
    ("categories", "Categories", "カテゴリ"),
    ("category", "Category", "カテゴリ"),
    ("component", "Component", "コンポーネント"),
    ("component_kind", "Component kind", "コンポーネント種別"),
    ("component_type", "Component type", "コンポーネント型"),
    ("components", "Components", "コンポーネント"),
    (
        "configuration",
        "Configuration parameters",
        "コンフィギュレーション",
    ),
    ("connects_to", "Connects to", "接続先"),
    ("constraint", "Constraint", "制約"),
    ("consumers", "Consumers (in ports)", "利用者 (入力ポート)"),
    ("creation_date", "Created", "作成日"),
    ("creator", "Creator", "作成者"),
    ("data_ports", "Data ports", "データポート"),
    ("data_type", "Data type", "データ型"),
    ("data_types", "Data types", "データ型"),
    ("default_value", "Default", "デフォルト値"),
    ("description", "Description", "概要"),
    ("diagnostics", "Diagnostics", "診断"),
    ("direction", "Direction", "方向"),
    ("execution_rate", "Execution rate", "実行周期"),
    ("execution_type", "Execution type", "実行型"),
    ("extra", "Extra properties", "追加プロパティ"),
    ("implemented", "Implemented", "実装"),
    ("in", "In", "入力"),
    ("inout", "Input and output", "入出力"),
    ("interface", "Interface", "インターフェース"),
    (
        "interfaces",
        "Service interfaces",
        "サービスインターフェース",
    ),
    ("language", "Language", "言語"),
    ("license", "License", "ライセンス"),
    ("max_instances", "Max instances", "最大インスタンス数"),
    ("name", "Name", "名前"),
    ("no", "no", "いいえ"),
    (
        "not_provided",
        "Required but provided by no component in this catalogue",
        "このカタログのどのコンポーネントも提供していない",
    ),
    ("out", "Out", "出力"),
    ("parameters", "System parameters", "システムパラメータ"),
    ("post_condition", "Post-condition", "事後条件"),
    ("pre_condition", "Pre-condition", "事前条件"),
    ("producers", "Producers (out ports)", "提供者 (出力ポート)"),
    ("properties", "Properties", "プロパティ"),
    ("provided", "Provided", "提供"),
    ("providers", "Providers", "提供コンポーネント"),
    ("reference", "Reference", "参考文献"),
    ("required", "Required", "要求"),
    (
        "requirers",
        "Consumers (required)",
        "利用コンポーネント (要求)",
    ),
    ("search", "Search", "検索"),
    (
        "search_placeholder",
        "Search components, ports, types…",
        "コンポーネント・ポート・型を検索…",
    ),
    ("service_ports", "Service ports", "サービスポート"),
    ("source", "Source", "ソース"),
    ("type", "Type", "型"),
    ("unit", "Unit", "単位"),
    ("update_date", "Updated", "更新日"),
    ("vendor", "Vendor", "ベンダー"),
    ("vendors", "Vendors", "ベンダー"),
    ("version", "Version", "バージョン"),
    ("version_up_logs", "Version history", "更新履歴"),
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
        assert_eq!(Lang::En.t("no-such-key"), "??");
    }
}
