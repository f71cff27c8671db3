//! Configuration value types (spec 2.3.8 `configuration.type`) and parsing of values written
//! as text for them.
//!
//! Profiles name the type of a configuration parameter in C++/IDL spelling: `int`, `double`,
//! `unsigned short int`, `std::string`, `std::vector<double>`, `sequence<long>` … This module
//! turns that spelling into a [`ValueType`] and checks that a value (a `defaultValue` or a
//! constraint literal) can be read as that type. Vector values are comma-separated, the way
//! OpenRTM's configuration admin reads them (`1.0, 2.0, 3.0`).
use crate::quote::Code;

/// A scalar type a configuration value can have.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScalarType {
    /// A signed or unsigned integer with its inclusive range.
    Integer { min: i128, max: i128 },
    /// `float` or `double`.
    Float,
    /// `bool` / `boolean`.
    Bool,
    /// `char` / `wchar`: exactly one character.
    Char,
    /// `string`, `std::string`, `wstring`: anything.
    Text,
}

/// The type of a configuration parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ValueType {
    Scalar(ScalarType),
    /// `vector<T>`, `std::vector<T>`, `sequence<T>`: comma-separated values of `T`.
    Vector(ScalarType),
    /// A type this tool does not know (a user struct, a typo): values are not checked.
    Unknown,
}

impl ValueType {
    /// Reads a type spelling (any case, extra spaces and a `std::` prefix allowed).
    pub fn parse(spelling: &str) -> ValueType {
        // Most profiles spell the type as one plain lower-case word (`double`, `std::string`),
        // which the normalisation below would leave as it is and which names no vector.
        let plain = spelling
            .bytes()
            .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_' || b == b':');
        if plain {
            return scalar(spelling).map_or(ValueType::Unknown, ValueType::Scalar);
        }
        Self::parse_spelled(spelling)
    }

    /// [`ValueType::parse`] for any spelling: spaces and case normalised first.
    fn parse_spelled(spelling: &str) -> ValueType {
        let norm = spelling
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
            .to_ascii_lowercase();
        let norm = norm
            .replace(" <", "<")
            .replace("< ", "<")
            .replace(" >", ">");
        for prefix in [
            "std::vector<",
            "vector<",
            "sequence<",
            "std::list<",
            "list<",
        ] {
            if let Some(inner) = norm.strip_prefix(prefix).and_then(|r| r.strip_suffix('>')) {
                return match scalar(inner.trim()) {
                    Some(s) => ValueType::Vector(s),
                    None => ValueType::Unknown,
                };
            }
        }
        if let Some(inner) = norm.strip_suffix("[]") {
            return scalar(inner.trim()).map_or(ValueType::Unknown, ValueType::Vector);
        }
        scalar(&norm).map_or(ValueType::Unknown, ValueType::Scalar)
    }

    /// The type of one element: the scalar itself, or the element type of a vector.
    pub fn element(self) -> Option<ScalarType> {
        match self {
            ValueType::Scalar(s) | ValueType::Vector(s) => Some(s),
            ValueType::Unknown => None,
        }
    }
}

fn int(min: i128, max: i128) -> Option<ScalarType> {
    Some(ScalarType::Integer { min, max })
}

/// Scalar type names (already lower-case, single-spaced).
fn scalar(name: &str) -> Option<ScalarType> {
    let name = name.strip_prefix("std::").unwrap_or(name);
    let name = name.strip_prefix("corba::").unwrap_or(name);
    match name {
        "short" | "short int" | "int16_t" => int(i16::MIN.into(), i16::MAX.into()),
        "unsigned short" | "unsigned short int" | "ushort" | "uint16_t" => int(0, u16::MAX.into()),
        "int" | "long" | "long int" | "signed" | "signed int" | "int32_t" => {
            int(i32::MIN.into(), i32::MAX.into())
        }
        "unsigned" | "unsigned int" | "unsigned long" | "unsigned long int" | "uint" | "ulong"
        | "uint32_t" => int(0, u32::MAX.into()),
        "long long" | "long long int" | "int64_t" => int(i64::MIN.into(), i64::MAX.into()),
        "unsigned long long" | "unsigned long long int" | "ulonglong" | "uint64_t" => {
            int(0, u64::MAX.into())
        }
        "octet" | "byte" | "unsigned char" | "uint8_t" => int(0, u8::MAX.into()),
        "float" | "double" | "long double" | "real" => Some(ScalarType::Float),
        "bool" | "boolean" => Some(ScalarType::Bool),
        "char" | "wchar" | "wchar_t" => Some(ScalarType::Char),
        "string" | "wstring" | "str" => Some(ScalarType::Text),
        _ => None,
    }
}

/// A scalar value read for its type.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scalar {
    Number(f64),
    Bool(bool),
}

/// Why a value does not parse for its type.
pub type ParseError = String;

/// Reads a boolean the way OpenRTM's `coil::stringTo<bool>` does: `true`/`false`, `1`/`0`,
/// `yes`/`no`, `on`/`off`, any case.
pub fn parse_config_bool(s: &str) -> Option<bool> {
    match s.trim().to_ascii_lowercase().as_str() {
        "true" | "1" | "yes" | "on" => Some(true),
        "false" | "0" | "no" | "off" => Some(false),
        _ => None,
    }
}

/// Reads a floating-point number (`1`, `-0.5`, `1e-3`, `inf`/`nan` are refused: a default
/// value should be finite).
pub fn parse_float(s: &str) -> Option<f64> {
    let s = s.trim();
    if s.is_empty()
        || !s
            .bytes()
            .all(|b| b.is_ascii_digit() || b"+-.eE".contains(&b))
    {
        return None;
    }
    s.parse::<f64>().ok().filter(|f| f.is_finite())
}

/// Reads one scalar for `ty`. `Text` and `Char` values have no numeric reading (`Ok(None)`).
pub fn parse_scalar(ty: ScalarType, s: &str) -> Result<Option<Scalar>, ParseError> {
    let t = s.trim();
    match ty {
        ScalarType::Integer { min, max } => {
            let digits = t.strip_prefix('+').unwrap_or(t);
            let n: i128 = digits
                .parse()
                .map_err(|_| format!("{} is not an integer", Code(t)))?;
            if n < min || n > max {
                return Err(format!(
                    "{n} is outside the range {min}..={max} of the type"
                ));
            }
            Ok(Some(Scalar::Number(n as f64)))
        }
        ScalarType::Float => parse_float(t)
            .map(|f| Some(Scalar::Number(f)))
            .ok_or_else(|| format!("{} is not a number", Code(t))),
        ScalarType::Bool => parse_config_bool(t)
            .map(|b| Some(Scalar::Bool(b)))
            .ok_or_else(|| {
                format!(
                    "{} is not a boolean (true/false, 1/0, yes/no, on/off)",
                    Code(t)
                )
            }),
        ScalarType::Char => {
            if s.chars().count() == 1 || t.chars().count() == 1 {
                Ok(None)
            } else {
                Err(format!("{} is not a single character", Code(s)))
            }
        }
        ScalarType::Text => Ok(None),
    }
}

/// Splits a vector value into its elements: comma-separated, each trimmed; an empty value is
/// an empty vector.
pub fn split_vector(s: &str) -> Vec<&str> {
    if s.trim().is_empty() {
        return Vec::new();
    }
    s.split(',').map(str::trim).collect()
}

/// Checks that `value` parses for `ty`. `Unknown` types always pass (they cannot be checked).
pub fn check_value(ty: ValueType, value: &str) -> Result<(), ParseError> {
    match ty {
        ValueType::Unknown => Ok(()),
        ValueType::Scalar(s) => parse_scalar(s, value).map(|_| ()),
        ValueType::Vector(s) => {
            for (i, e) in split_vector(value).into_iter().enumerate() {
                parse_scalar(s, e).map_err(|m| format!("element {i}: {m}"))?;
            }
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The plain-word shortcut reads every spelling as the normalising reader does.
    #[test]
    fn plain_words_read_as_normalised() {
        const PARTS: &[&str] = &[
            "std::", "corba::", "vector", "<", ">", "[]", " ", "\t", "unsigned", "long", "short",
            "int", "double", "Double", "string", "bool", "uint8_t", "_", "x", "\u{3000}", "é",
        ];
        crate::test_text::agrees(
            (PARTS, 6, None),
            &[" unsigned"],
            ValueType::parse,
            ValueType::parse_spelled,
        );
    }

    #[test]
    fn type_spellings() {
        assert_eq!(
            ValueType::parse("double"),
            ValueType::Scalar(ScalarType::Float)
        );
        assert_eq!(
            ValueType::parse("unsigned short int"),
            ValueType::Scalar(ScalarType::Integer { min: 0, max: 65535 })
        );
        assert_eq!(
            ValueType::parse("unsigned int "),
            ValueType::parse("unsigned int")
        );
        assert_eq!(
            ValueType::parse("String"),
            ValueType::Scalar(ScalarType::Text)
        );
        assert_eq!(
            ValueType::parse("std::vector<double>"),
            ValueType::Vector(ScalarType::Float)
        );
        assert_eq!(
            ValueType::parse("sequence< long >"),
            ValueType::Vector(ScalarType::Integer {
                min: i32::MIN.into(),
                max: i32::MAX.into()
            })
        );
        assert_eq!(ValueType::parse("MyStruct"), ValueType::Unknown);
        assert_eq!(ValueType::parse("vector<MyStruct>"), ValueType::Unknown);
    }

    #[test]
    fn values() {
        let short = ValueType::parse("short");
        assert!(check_value(short, "-32768").is_ok());
        assert!(check_value(short, "32768").is_err());
        assert!(check_value(short, "1.5").is_err());
        assert!(check_value(ValueType::parse("octet"), "256").is_err());
        assert!(check_value(ValueType::parse("double"), "1e-3").is_ok());
        assert!(check_value(ValueType::parse("double"), "abc").is_err());
        assert!(check_value(ValueType::parse("double"), "nan").is_err());
        assert!(check_value(ValueType::parse("bool"), "TRUE").is_ok());
        assert!(check_value(ValueType::parse("bool"), "maybe").is_err());
        assert!(check_value(ValueType::parse("char"), "a").is_ok());
        assert!(check_value(ValueType::parse("char"), "ab").is_err());
        assert!(check_value(ValueType::parse("vector<int>"), "1, 2,3").is_ok());
        assert!(check_value(ValueType::parse("vector<int>"), "").is_ok());
        assert!(check_value(ValueType::parse("vector<int>"), "1,x").is_err());
        assert!(check_value(ValueType::Unknown, "whatever").is_ok());
    }
}
