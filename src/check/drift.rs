//! RTC801–RTC810: where a component's code and its profile disagree
//! ([`crate::implementation::drift`]), each at the source line with the profile element as its
//! related location, and what the code registers that cannot be verified statically.

use crate::catalog::Component;
use crate::diagnostic::Diagnostic;
use crate::implementation::drift::{codes, Drift, DriftKind};
use crate::quote::Code;

/// The findings of one component's implementation.
pub(crate) fn findings(c: &Component) -> Vec<Diagnostic> {
    let Some(imp) = &c.implementation else {
        return Vec::new();
    };
    let mut out: Vec<Diagnostic> = imp.drift.iter().map(|d| finding(c, d)).collect();
    for u in &imp.unverified {
        let d = Diagnostic::info(
            codes::UNVERIFIED,
            &u.at.file,
            format!("could not verify {}: {}", u.what, Code(&u.construct)),
        )
        .at(u.at.pos)
        .with_hint("nothing to change: what the code builds at run time is not compared with the profile; keep the profile's elements in step with it by hand");
        // A component recovered from its code has no profile to point at.
        out.push(if c.recovered.is_some() {
            d
        } else {
            d.with_related(&c.source, None, "the profile")
        });
    }
    let p = &c.profile;
    let declares =
        !(p.data_ports.is_empty() && p.service_ports.is_empty() && p.configurations().is_empty());
    if imp.registers_nothing() && declares && imp.unverified.is_empty() {
        let file = imp.files.first().map_or(c.source.as_str(), String::as_str);
        let base = imp
            .class
            .as_ref()
            .and_then(|k| k.bases.first())
            .map(|b| format!(" (the class derives from {})", Code(b)))
            .unwrap_or_default();
        out.push(
            Diagnostic::info(
                codes::UNVERIFIED,
                file,
                format!("could not verify the ports and parameters: the files read register none{base}; they may be registered in a base class, a library or another file"),
            )
            .with_related(&c.source, None, "the profile")
            .with_hint("if another file registers them, name the component's files in rtcdoc.toml ([[implementation.component]] name = \"…\", files = [\"src/….cpp\"])"),
        );
    }
    out
}

/// RTC812: `c` has code and no profile, and is documented from its code.
pub(crate) fn recovered(
    c: &Component,
    r: &crate::implementation::recover::Recovered,
) -> Diagnostic {
    let pos = c
        .implementation
        .as_ref()
        .and_then(|i| i.spec.first())
        .map(|s| s.at.pos)
        .unwrap_or_default();
    let folder = crate::implementation::recover::component_folder(&c.source);
    let unread = if r.unread.is_empty() {
        String::new()
    } else {
        let list: Vec<String> = r
            .unread
            .iter()
            .map(|u| {
                if u.written.contains(char::is_whitespace) {
                    format!("{} ({})", u.field, u.written)
                } else {
                    format!("{} ({})", u.field, Code(&u.written))
                }
            })
            .collect();
        format!("; not read from the code: {}", list.join(", "))
    };
    Diagnostic::info(
        crate::implementation::codes::RECOVERED,
        &c.source,
        format!(
            "{} has no profile: it is documented from its code{unread}",
            Code(c.profile.name())
        ),
    )
    .at(pos)
    .with_hint(crate::implementation::recover::extract_hint(folder))
}

fn finding(c: &Component, d: &Drift) -> Diagnostic {
    let el = Code(&d.element);
    let p = d.profile.as_deref().unwrap_or("");
    let k = d.code.as_deref().unwrap_or("");
    let (message, hint) = match d.kind {
        DriftKind::OnlyInProfile => (
            format!("{el} is in the profile ({p}) but the code does not register it"),
            "register it in the code (the generated onInitialize), or remove it from the profile if the component no longer has it (RTCBuilder, RTC.xml)",
        ),
        DriftKind::OnlyInCode => (
            format!("the code registers {el} ({k}), which the profile does not declare"),
            "add it to the profile (RTCBuilder, RTC.xml) so that it is documented, or remove the registration",
        ),
        DriftKind::NameCase => (
            format!("{el}: the profile says {} and the code {}, which differ only in case", Code(p), Code(k)),
            "OpenRTM names are case-sensitive (a connector to the profile's name fails): rename one of them so both spell it the same",
        ),
        DriftKind::DataType => (
            format!("{el}: the profile says {} and the code {}", Code(p), Code(k)),
            "change the profile's type to what the code uses, or the code's declaration to the profile's type (connectors are made by the profile's type)",
        ),
        DriftKind::Direction => (
            format!("{el}: the profile says {} and the code registers it as {}", Code(p), Code(k)),
            "make the profile's port type (or interface direction) say what the code registers",
        ),
        DriftKind::Default => (
            format!("{el}: the profile's default is {} and the code's {}", Code(p), Code(k)),
            "make the code's default (bindParameter, the spec array's conf.default) and the profile's defaultValue the same",
        ),
        DriftKind::CallbackUnmarked => (
            format!("{el} is implemented in the code, but the profile marks it {p}"),
            "mark the action implemented in the profile (RTCBuilder's Activity tab, rtc:implemented=\"true\") and document what it does",
        ),
        DriftKind::CallbackMissing => (
            format!("{el}: the profile marks it {p}, but the code does not define it (commented out or removed)"),
            "mark the action not implemented in the profile, or define the callback in the code",
        ),
        DriftKind::SpecValue => (
            format!("{el}: the profile says {} and the spec array {}", Code(p), Code(k)),
            "regenerate the spec array from the profile (RTCBuilder) or edit the one that is stale",
        ),
    };
    let mut diag = match &d.at {
        Some(at) => Diagnostic::warning(d.kind.code(), &at.file, message)
            .at(at.pos)
            .with_related(&c.source, d.profile_pos, "the profile says it here"),
        // Nothing in the code to point at: the profile element, with the code's main file.
        None => {
            let mut diag = Diagnostic::warning(d.kind.code(), &c.source, message);
            if let Some(p) = d.profile_pos {
                diag = diag.at(p);
            }
            match c.implementation.as_ref().and_then(|i| i.files.first()) {
                Some(f) => diag.with_related(f, None, "the code read"),
                None => diag,
            }
        }
    };
    diag = diag.with_hint(hint);
    diag
}
