//! Template functions for the markup every component page repeats for each row: the labelled
//! fields of a section, a link to a type or interface page, and the "connects to" list. They
//! are plain functions rather than template macros because a 10,000-component site calls them
//! about 400,000 times, and a macro call is the most expensive thing a minijinja template does.
//! Values are escaped exactly as `{{ … }}` escapes them; only `Field.html` is printed as is.

use super::svg::esc_into;
use minijinja::{Error, Value};

/// Appends a value as `{{ v }}` would print it.
fn put(out: &mut String, v: &Value) {
    if v.is_undefined() {
        return;
    }
    // Writing to a String cannot fail.
    let _ = match v.as_str() {
        Some(s) if v.is_safe() => {
            out.push_str(s);
            Ok(())
        }
        Some(s) => esc_into(out, s),
        None => esc_into(out, &v.to_string()),
    };
}

/// Appends a value as `{{ v|safe }}` would print it.
/// `{{ v|wbr }}`: `v` escaped with `<wbr>` between the words of a name; nothing for an
/// undefined or none value, as `{{ … }}` prints them.
pub(super) fn put_wbr(out: &mut String, v: &Value) {
    if v.is_undefined() || v.is_none() {
        return;
    }
    // Writing to a String cannot fail.
    let _ = match v.as_str() {
        Some(s) => crate::render::html::svg::esc_wbr_into(out, s),
        None => crate::render::html::svg::esc_wbr_into(out, &v.to_string()),
    };
}

fn put_raw(out: &mut String, v: &Value) {
    match v.as_str() {
        Some(s) => out.push_str(s),
        None if v.is_undefined() => {}
        None => out.push_str(&v.to_string()),
    }
}

/// `fields(list)`: a `<dl class="fields">` of [Field]s (`{label, text?, html?}`); nothing for an
/// empty list.
pub fn fields(list: Value) -> Result<Value, Error> {
    let mut out = String::new();
    if list.is_true() {
        out.push_str("<dl class=\"fields\">\n");
        for f in list.try_iter()? {
            out.push_str("<dt>");
            put(&mut out, &f.get_attr("label")?);
            out.push_str("</dt><dd>");
            let html = f.get_attr("html")?;
            if html.is_true() {
                put_raw(&mut out, &html);
            } else {
                put(&mut out, &f.get_attr("text")?);
            }
            out.push_str("</dd>\n");
        }
        out.push_str("</dl>");
    }
    Ok(Value::from_safe_string(out))
}

/// `type_link(type_ref)`: the type name in `<code>`, linked when `type_ref.href` is set.
pub fn type_link(r: Value) -> Result<Value, Error> {
    let mut out = String::new();
    if r.is_true() {
        let href = r.get_attr("href")?;
        if href.is_true() {
            out.push_str("<a href=\"");
            put(&mut out, &href);
            out.push_str("\"><code>");
            put_wbr(&mut out, &r.get_attr("text")?);
            out.push_str("</code></a>");
        } else {
            out.push_str("<code>");
            put_wbr(&mut out, &r.get_attr("text")?);
            out.push_str("</code>");
        }
    }
    Ok(Value::from_safe_string(out))
}

/// `peers(row)`: the `<ul class="peers">` of `row.peers` (Links) plus `row.peers_more`, or a
/// dash when there are none.
pub fn peers(row: Value) -> Result<Value, Error> {
    let mut out = String::new();
    let list = row.get_attr("peers")?;
    if !list.is_true() {
        out.push_str("<span class=\"none\">—</span>");
        return Ok(Value::from_safe_string(out));
    }
    out.push_str("<ul class=\"peers\">\n");
    for l in list.try_iter()? {
        out.push_str("<li><a href=\"");
        put(&mut out, &l.get_attr("href")?);
        out.push_str("\">");
        put(&mut out, &l.get_attr("text")?);
        out.push_str("</a></li>\n");
    }
    let more = row.get_attr("peers_more")?;
    if more.is_true() {
        out.push_str("<li class=\"more\"><a href=\"");
        put(&mut out, &more.get_attr("href")?);
        out.push_str("\">");
        put(&mut out, &more.get_attr("text")?);
        out.push_str("</a></li>\n");
    }
    out.push_str("</ul>");
    Ok(Value::from_safe_string(out))
}

#[cfg(test)]
mod tests {
    use super::*;
    use minijinja::{context, Environment};

    /// The template macros these functions replace; their output must stay the same.
    const MACROS: &str = r#"{% macro m_fields(list) %}{% if list %}<dl class="fields">
{% for f in list %}<dt>{{ f.label }}</dt><dd>{% if f.html %}{{ f.html|safe }}{% else %}{{ f.text }}{% endif %}</dd>
{% endfor %}</dl>{% endif %}{% endmacro %}
{%- macro m_type_link(r) %}{% if r %}{% if r.href %}<a href="{{ r.href }}"><code>{{ r.text|wbr }}</code></a>{% else %}<code>{{ r.text|wbr }}</code>{% endif %}{% endif %}{% endmacro %}
{%- macro m_peers(p) %}{% if p.peers %}<ul class="peers">
{% for l in p.peers %}<li><a href="{{ l.href }}">{{ l.text }}</a></li>
{% endfor %}{% if p.peers_more %}<li class="more"><a href="{{ p.peers_more.href }}">{{ p.peers_more.text }}</a></li>
{% endif %}</ul>{% else %}<span class="none">—</span>{% endif %}{% endmacro %}"#;

    fn env() -> Environment<'static> {
        let mut env = Environment::new();
        env.set_formatter(super::super::formatter);
        env.add_function("fields", fields);
        env.add_filter("wbr", super::super::wbr);
        env.add_function("type_link", type_link);
        env.add_function("peers", peers);
        env.add_template("m.html", MACROS).unwrap();
        env
    }

    fn both(env: &Environment<'_>, call: &str, ctx: Value) -> (String, String) {
        let old = format!("{{% from \"m.html\" import m_{call} %}}{{{{ m_{call}(x) }}}}");
        let new = format!("{{{{ {call}(x) }}}}");
        let r = |src: &str| {
            env.render_named_str("t.html", src, ctx.clone())
                .unwrap_or_else(|e| panic!("{src}: {e}"))
        };
        (r(&old), r(&new))
    }

    #[test]
    fn same_output_as_the_macros() {
        let env = env();
        let hostile = "<script>alert('x')</script> & \"q\"";
        let field_lists = [
            context! { x => Vec::<Value>::new() },
            context! { x => () },
            context! { x => vec![
                context! { label => hostile, text => hostile },
                context! { label => "L", html => "<p>ok</p>" },
                context! { label => "N", text => 42 },
                context! { label => "E", html => "", text => "fallback" },
            ] },
        ];
        for ctx in field_lists {
            let (old, new) = both(&env, "fields", ctx);
            assert_eq!(old, new);
        }
        for ctx in [
            context! { x => () },
            context! { x => context! { text => hostile } },
            context! { x => context! { text => "RTC::TimedLong", href => "../types/a\"b.html" } },
        ] {
            let (old, new) = both(&env, "type_link", ctx);
            assert_eq!(old, new);
        }
        for ctx in [
            context! { x => context! {} },
            context! { x => context! { peers => Vec::<Value>::new() } },
            context! { x => context! {
                peers => vec![context! { text => hostile, href => "a.html#p" }],
                peers_more => context! { text => "+3", href => "../types/t.html" },
            } },
            context! { x => context! { peers => vec![context! { text => "b", href => "b.html" }] } },
        ] {
            let (old, new) = both(&env, "peers", ctx);
            assert_eq!(old, new);
        }
    }

    #[test]
    fn labels_object_reads_like_a_map() {
        let mut env = Environment::new();
        let lang = crate::i18n::Lang::En;
        env.add_global("t", Value::from_object(super::super::Labels::new(lang)));
        let out = env
            .render_str(
                "{{ t.data_ports }}|{{ t.nope is undefined }}|{{ t|length }}|{{ (t|items|first)[0] }}",
                (),
            )
            .unwrap();
        let n = lang.labels().count();
        let first = lang.labels().map(|(k, _)| k).min().unwrap();
        assert_eq!(out, format!("{}|True|{n}|{first}", lang.t("data_ports")));
    }

    #[test]
    fn profile_text_is_escaped() {
        let env = env();
        let (_, new) = both(
            &env,
            "fields",
            context! { x => vec![context! { label => "<b>", text => "<script>x</script>" }] },
        );
        assert!(!new.contains("<script>") && !new.contains("<b>"), "{new}");
        assert!(new.contains("&lt;script&gt;"), "{new}");
    }
}
