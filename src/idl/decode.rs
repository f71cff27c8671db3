//! Bytes → text. IDL files carry no encoding declaration, so the encoding is detected:
//! valid UTF-8 (with or without BOM) is UTF-8; otherwise EUC-JP, then Shift_JIS, whichever
//! decodes without a replacement character (EUC-JP first: OpenRTM's own RTC.idl is EUC-JP, and
//! EUC-JP byte pairs are more often also valid Shift_JIS than the reverse). When neither
//! decodes cleanly, EUC-JP with replacement characters is used and the caller warns.

/// The decoded text, the encoding's name and whether bytes had to be replaced.
pub(crate) struct Decoded {
    pub text: String,
    pub encoding: &'static str,
    pub lossy: bool,
}

/// Text that is not UTF-8 read as EUC-JP, else Shift_JIS, when one of them decodes every byte
/// (EUC-JP first, see the module's note); with the encoding's name. Also for READMEs, which
/// declare no encoding either.
pub(crate) fn japanese(body: &[u8]) -> Option<(String, &'static str)> {
    [encoding_rs::EUC_JP, encoding_rs::SHIFT_JIS]
        .into_iter()
        .find_map(|enc| {
            enc.decode_without_bom_handling_and_without_replacement(body)
                .map(|t| (t.into_owned(), enc.name()))
        })
}

pub(crate) fn decode(bytes: &[u8]) -> Decoded {
    let body = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    if let Ok(s) = std::str::from_utf8(body) {
        return Decoded {
            text: s.to_string(),
            encoding: "UTF-8",
            lossy: false,
        };
    }
    if let Some((text, encoding)) = japanese(body) {
        return Decoded {
            text,
            encoding,
            lossy: false,
        };
    }
    let (text, _) = encoding_rs::EUC_JP.decode_without_bom_handling(body);
    Decoded {
        text: text.into_owned(),
        encoding: encoding_rs::EUC_JP.name(),
        lossy: true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn detects_each_encoding() {
        assert_eq!(decode(b"\xEF\xBB\xBFmodule").encoding, "UTF-8");
        assert_eq!(decode(b"\xEF\xBB\xBFmodule").text, "module");
        let (euc, _, _) = encoding_rs::EUC_JP.encode("// 時刻\n");
        let d = decode(&euc);
        assert_eq!(
            (d.encoding, d.text.as_str(), d.lossy),
            ("EUC-JP", "// 時刻\n", false)
        );
        // A Shift_JIS byte pair that is not valid EUC-JP (0x81 lead byte).
        let (sjis, _, _) = encoding_rs::SHIFT_JIS.encode("// ソース\n");
        let d = decode(&sjis);
        assert_eq!((d.encoding, d.text.as_str()), ("Shift_JIS", "// ソース\n"));
        let d = decode(b"\xFF\xFF\xFF");
        assert!(d.lossy);
    }
}
