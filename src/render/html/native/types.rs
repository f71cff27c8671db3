//! The data type and interface pages: `type.html` and `interface.html` (with the macros
//! `uses_table`, `idl_definition` and `idl_file_section` of `macros.html`) as Rust code.

use super::{base_bottom, base_top, history_table, Globals, Head, Out};
use crate::render::html::{IdlFilePage, InterfaceUse, Link, PortUse, TypePage};
use crate::render::idl_view::{DefinitionView, OperationView, TypeRef};
use crate::render::view::types::TypeKind;

/// A data type's or interface's page, as `type.html` or `interface.html` (extending
/// `base.html`, with the macros of `macros.html`) renders `page`.
pub(in crate::render::html) fn type_page(page: &TypePage, g: &Globals<'_>) -> String {
    let mut o = Out {
        buf: String::with_capacity(8 * 1024),
        g,
    };
    base_top(
        &mut o,
        &Head {
            root: page.root,
            title: &page.title,
            description: "",
            crumbs: &page.crumbs,
            current: &page.name,
        },
    );
    let data = page.kind == TypeKind::Data;
    o.label_in(
        "\n<h1><span class=\"kind\">",
        if data { "data_type" } else { "interface" },
        "</span> ",
    );
    o.code(&page.name);
    o.raw("</h1>\n");
    super::stability_line(&mut o, page.stability.as_ref());
    if !data {
        if page.unprovided == Some(true) {
            o.label_in(
                "<p class=\"warning flag\" role=\"note\">⚠ ",
                "not_provided",
                "</p>",
            );
        }
        o.raw("\n");
    }
    o.raw("<dl class=\"fields\">\n");
    code_list(&mut o, "spellings", &page.spellings);
    o.raw("\n");
    if !page.idl_files.is_empty() {
        code_list(&mut o, "idl_files", &page.idl_files);
    }
    o.raw("\n</dl>\n");
    match &page.def {
        Some(def) => idl_definition(&mut o, def, page.root),
        None => o.label_in("<p class=\"no-definition\">", "idl_no_definition", "</p>"),
    }
    o.raw("\n");
    if let Some(f) = &page.idl_file {
        idl_file_section(&mut o, f);
        o.raw("\n");
    }
    if data {
        data_uses(&mut o, page);
    } else {
        if !page.used_by.is_empty() {
            interface_uses(&mut o, &page.used_by, page.used_by_count);
            o.raw("\n");
        }
        let providers = none_or(&page.providers);
        let requirers = none_or(&page.requirers);
        if providers.is_empty() && requirers.is_empty() && page.others.is_empty() {
            o.label_in("<p class=\"none\">", "interface_no_components", "</p>\n");
        }
        uses_section(&mut o, "providers", "providers", none_or(&page.providers));
        o.raw("\n");
        uses_section(&mut o, "requirers", "requirers", none_or(&page.requirers));
        o.raw("\n");
    }
    if !page.others.is_empty() {
        counted_section(&mut o, "others", "others", page.others.len());
        uses_table(&mut o, &page.others);
        o.raw("\n</section>");
    }
    o.raw("\n");
    base_bottom(&mut o);
    o.buf
}

/// The list of a data type's page kind, empty when absent.
fn none_or<T>(list: &Option<Vec<T>>) -> &[T] {
    list.as_deref().unwrap_or_default()
}

/// `type.html`'s sections after the IDL file: contained in, producers, consumers, carried by.
fn data_uses(o: &mut Out<'_>, page: &TypePage) {
    let contained_in = none_or(&page.contained_in);
    if !contained_in.is_empty() {
        link_section(o, "contained-in", "idl_contained_in", contained_in, true);
    }
    o.raw("\n");
    if !page.used_by.is_empty() {
        interface_uses(o, &page.used_by, page.used_by_count);
        o.raw("\n");
    }
    uses_section(o, "producers", "producers", none_or(&page.producers));
    o.raw("\n");
    uses_section(o, "consumers", "consumers", none_or(&page.consumers));
    o.raw("\n");
    let carried_by = none_or(&page.carried_by);
    if !carried_by.is_empty() {
        link_section(o, "system-connectors", "sys_carried_by", carried_by, false);
        o.raw("\n");
    }
}

/// `<span class="count">n</span>` after a heading's label.
fn count(o: &mut Out<'_>, n: usize) {
    o.raw(" <span class=\"count\">");
    o.raw(itoa::Buffer::new().format(n));
    o.raw("</span>");
}

/// `<h2>{{ t.key }} <span class="count">n</span></h2>` in a section `id`.
fn counted_section(o: &mut Out<'_>, id: &str, key: &str, n: usize) {
    o.raw("<section id=\"");
    o.raw(id);
    o.raw("\">\n<h2>");
    o.label(key);
    count(o, n);
    o.raw("</h2>\n");
}

/// A section listing linked names (`contained_in`, in code, or `carried_by`).
fn link_section(o: &mut Out<'_>, id: &str, key: &str, links: &[Link], code: bool) {
    counted_section(o, id, key, links.len());
    o.raw("<ul class=\"links\">");
    for c in links {
        o.raw("<li>");
        if code {
            o.code_link(Some(&c.href), &c.text);
        } else {
            o.link(&c.href, &c.text);
        }
        o.raw("</li>");
    }
    o.raw("</ul>\n</section>");
}

/// A section of uses (producers, consumers, providers, requirers): their table, or a dash.
fn uses_section(o: &mut Out<'_>, id: &str, key: &str, list: &[PortUse]) {
    counted_section(o, id, key, list.len());
    if list.is_empty() {
        o.raw("<p class=\"none\">—</p>");
    } else {
        uses_table(o, list);
    }
    o.raw("\n</section>");
}

/// `<dt>{{ t.key }}</dt><dd>` and the items in code, comma-separated.
fn code_list(o: &mut Out<'_>, key: &str, items: &[String]) {
    o.label_in("<dt>", key, "</dt><dd>");
    for (i, s) in items.iter().enumerate() {
        if i > 0 {
            o.raw(", ");
        }
        o.code(s);
    }
    o.raw("</dd>");
}

/// The `uses_table` macro.
fn uses_table(o: &mut Out<'_>, list: &[PortUse]) {
    o.table_wrap("uses", &["component", "port"]);
    for u in list {
        o.raw("<tr><th scope=\"row\">");
        o.link(&u.component.href, &u.component.text);
        o.raw("</th>");
        o.td("port");
        o.code_link(Some(&u.port.href), &u.port.text);
        o.raw("</td></tr>\n");
    }
    o.raw("</tbody>\n</table>\n</div>");
}

/// The `interface_uses` macro: the operations and attributes of interfaces using the type.
fn interface_uses(o: &mut Out<'_>, list: &[InterfaceUse], count_: usize) {
    counted_section(o, "used-by-interfaces", "idl_used_by", count_);
    o.table_wrap("idl-uses", &["interface", "idl_member", "idl_use"]);
    for u in list {
        o.raw("<tr><th scope=\"row\">");
        o.code_link(Some(&u.interface.href), &u.interface.text);
        o.raw("</th>");
        o.td("idl_member");
        o.code_link(Some(&u.member.href), &u.member.text);
        o.raw("</td>");
        o.cell("idl_use", &u.how, "</tr>\n");
    }
    o.raw("</tbody>\n</table>\n</div>\n</section>");
}

/// The `idl_file_section` macro.
fn idl_file_section(o: &mut Out<'_>, f: &IdlFilePage) {
    o.raw("<section id=\"idl-file\">\n<h2>");
    o.label("idl_file");
    o.raw("</h2>\n<p>");
    o.label("source");
    o.raw(": ");
    o.code_link(f.source_url.as_deref().filter(|u| !u.is_empty()), &f.file);
    o.raw("</p>\n");
    if !f.history.is_empty() {
        o.label_in("<p>", "history_intro_idl", "</p>\n");
        history_table(o, &f.history, f.older.as_deref(), f.history_page.as_deref());
        if let Some(href) = f.history_page.as_deref().filter(|h| !h.is_empty()) {
            o.raw("<p><a href=\"");
            o.text(href);
            o.raw("\">");
            o.label("history_full");
            o.raw("</a></p>\n");
        }
    }
    o.raw("</section>");
}

/// The `idl_type` macro: a type as written, linked to its page when it has one.
fn idl_type(o: &mut Out<'_>, ty: &TypeRef, root: &str) {
    match ty.page.as_deref().filter(|p| !p.is_empty()) {
        Some(page) => {
            o.raw("<a href=\"");
            o.text(root);
            o.text(page);
            o.raw("\"><code>");
            o.name(&ty.text);
            o.raw("</code></a>");
        }
        None => o.code(&ty.text),
    }
}

/// The types, each by `idl_type`, separated by `sep`.
fn idl_types(o: &mut Out<'_>, types: &[TypeRef], sep: &str, root: &str) {
    for (i, t) in types.iter().enumerate() {
        if i > 0 {
            o.raw(sep);
        }
        idl_type(o, t, root);
    }
}

/// `<p>{{ t.key }}: {{ idl_type(ty) }}</p>` when there is a type.
fn labelled_type(o: &mut Out<'_>, key: &str, ty: &Option<TypeRef>, root: &str) {
    if let Some(ty) = ty {
        o.label_in("<p>", key, ": ");
        idl_type(o, ty, root);
        o.raw("</p>");
    }
    o.raw("\n");
}

/// The `idl_definition` macro.
fn idl_definition(o: &mut Out<'_>, def: &DefinitionView, root: &str) {
    o.raw("<section id=\"definition\">\n<h2>");
    o.label("idl_definition");
    o.raw(" <span class=\"count\">");
    o.code(def.kind);
    o.raw("</span></h2>\n<p class=\"defined-in\">");
    o.label("idl_defined_in");
    o.raw(" <code>");
    o.name(&def.file);
    o.raw(":");
    o.raw(itoa::Buffer::new().format(def.line));
    o.raw("</code>");
    if !def.repository_id.is_empty() {
        o.raw(" · ");
        o.code(&def.repository_id);
    }
    o.raw("</p>\n");
    o.text_if("<p>", &def.brief, "</p>");
    o.raw("\n");
    o.text_if("<p class=\"details\">", &def.details, "</p>");
    o.raw("\n");
    labelled_type(o, "idl_aliases", &def.aliases, root);
    labelled_type(o, "idl_switch", &def.switch, root);
    if !def.bases.is_empty() {
        o.label_in("<p>", "idl_bases", ": ");
        idl_types(o, &def.bases, ", ", root);
        o.raw("</p>");
    }
    o.raw("\n");
    idl_fields(o, def, root);
    idl_values(o, def);
    idl_operations(o, def, root);
    idl_inherited(o, def, root);
    idl_attributes(o, def, root);
    o.raw("</section>");
}

/// The fields table of `idl_definition`.
fn idl_fields(o: &mut Out<'_>, def: &DefinitionView, root: &str) {
    if !def.fields.is_empty() {
        let union = def.kind == "union";
        let heads: &[&str] = if union {
            &["idl_cases", "idl_field", "type", "description"]
        } else {
            &["idl_field", "type", "description"]
        };
        o.raw("<div class=\"table-wrap\">");
        o.table_head("idl-fields", heads);
        o.raw("<tbody>\n");
        for f in &def.fields {
            o.raw("<tr id=\"field-");
            o.text(&f.name);
            o.raw("\">");
            if union {
                o.td("idl_cases");
                o.code(&f.labels);
                o.raw("</td>");
            }
            o.td("idl_field");
            o.raw("<code>");
            o.name(&f.name);
            o.text(&f.array);
            o.raw("</code></td>");
            type_and_doc(o, &f.ty, &f.doc, root);
        }
        o.raw("</tbody></table></div>");
    }
    o.raw("\n");
}

/// The last two cells of a field's or attribute's row: its type and its description.
fn type_and_doc(o: &mut Out<'_>, ty: &TypeRef, doc: &str, root: &str) {
    o.td("type");
    idl_type(o, ty, root);
    o.raw("</td>");
    o.cell("description", doc, "</tr>\n");
}

/// `<tr id="<prefix><name>">` and the open name cell holding `name` as code.
fn named_row(o: &mut Out<'_>, prefix: &str, name: &str) {
    o.raw("<tr id=\"");
    o.raw(prefix);
    o.text(name);
    o.raw("\">");
    o.td("name");
    o.code(name);
}

/// The values table of `idl_definition` (an enum's).
fn idl_values(o: &mut Out<'_>, def: &DefinitionView) {
    if !def.values.is_empty() {
        o.label_in("<h3>", "idl_values", "</h3>\n<div class=\"table-wrap\">");
        o.raw("<table class=\"idl-values\"><thead><tr>");
        o.head_cells(&["name", "description"]);
        o.raw("</tr></thead>\n<tbody>\n");
        for v in &def.values {
            named_row(o, "value-", &v.name);
            o.raw("</td>");
            o.cell("description", &v.doc, "</tr>\n");
        }
        o.raw("</tbody></table></div>");
    }
    o.raw("\n");
}

/// The operations of `idl_definition` (an interface's).
fn idl_operations(o: &mut Out<'_>, def: &DefinitionView, root: &str) {
    if !def.operations.is_empty() {
        o.label_in("<h3>", "idl_operations", "</h3>\n");
        for op in &def.operations {
            idl_operation(o, op, root);
        }
    }
    o.raw("\n");
}

/// The inherited operations and attributes of `idl_definition` (an interface's), lists per
/// base, each member linked to its place on the base's page.
fn idl_inherited(o: &mut Out<'_>, def: &DefinitionView, root: &str) {
    for g in &def.inherited {
        o.label_in("<h3>", "idl_inherited_from", " ");
        idl_type(o, &g.base, root);
        o.raw("</h3>\n");
        let page = g.base.page.as_deref().filter(|p| !p.is_empty());
        if !g.operations.is_empty() {
            o.raw("<ul class=\"idl-inherited\">");
            for op in &g.operations {
                inherited_item(o, root, page, "#op-", &op.name);
                o.text_if(": ", &op.doc, "");
                o.raw("</li>\n");
            }
            o.raw("</ul>\n");
        }
        if !g.attributes.is_empty() {
            o.label_in(
                "<p>",
                "idl_attributes",
                ":</p>\n<ul class=\"idl-inherited\">",
            );
            for a in &g.attributes {
                inherited_item(o, root, page, "#attr-", &a.name);
                if a.readonly {
                    o.label_in(" (", "idl_readonly", ")");
                }
                o.text_if(": ", &a.doc, "");
                o.raw("</li>\n");
            }
            o.raw("</ul>\n");
        }
    }
    o.raw("\n");
}

/// `<li>` and member `name` of a base, linked to `page#<anchor><name>` when the base has a page.
fn inherited_item(o: &mut Out<'_>, root: &str, page: Option<&str>, anchor: &str, name: &str) {
    o.raw("<li>");
    match page {
        Some(page) => {
            o.raw("<a href=\"");
            o.text(root);
            o.text(page);
            o.raw(anchor);
            o.text(name);
            o.raw("\"><code>");
            o.name(name);
            o.raw("</code></a>");
        }
        None => o.code(name),
    }
}

/// One operation: its signature, documentation and parameters.
fn idl_operation(o: &mut Out<'_>, op: &OperationView, root: &str) {
    o.raw("<div class=\"idl-operation\" id=\"op-");
    o.text(&op.name);
    o.raw("\">\n<p class=\"signature\">");
    if op.oneway {
        o.raw("<code>oneway </code>");
    }
    idl_type(o, &op.returns, root);
    o.raw(" <code><strong>");
    o.name(&op.name);
    o.raw("</strong>(</code>");
    for (i, p) in op.params.iter().enumerate() {
        o.raw("<code>");
        o.text(p.direction);
        o.raw(" </code>");
        idl_type(o, &p.ty, root);
        o.raw(" ");
        o.code(&p.name);
        if i + 1 < op.params.len() {
            o.raw("<code>, </code>");
        }
    }
    o.raw("<code>)</code>");
    if !op.raises.is_empty() {
        o.raw(" <code>raises (</code>");
        idl_types(o, &op.raises, "<code>, </code>", root);
        o.raw("<code>)</code>");
    }
    o.raw("</p>\n");
    o.text_if("<p>", &op.doc, "</p>");
    o.raw("\n");
    if !op.params.is_empty() {
        o.raw("<dl class=\"params\">");
        for p in op.params.iter().filter(|p| !p.doc.is_empty()) {
            o.raw("<dt>");
            o.code(&p.name);
            o.raw(" (");
            o.text(p.direction);
            o.raw(")</dt><dd>");
            o.text(&p.doc);
            o.raw("</dd>");
        }
        if !op.returns_doc.is_empty() {
            o.label_in("<dt>", "idl_returns", "</dt><dd>");
            o.text(&op.returns_doc);
            o.raw("</dd>");
        }
        o.raw("</dl>");
    }
    o.raw("\n</div>\n");
}

/// The attributes table of `idl_definition` (an interface's).
fn idl_attributes(o: &mut Out<'_>, def: &DefinitionView, root: &str) {
    if !def.attributes.is_empty() {
        o.label_in(
            "<h3>",
            "idl_attributes",
            "</h3>\n<div class=\"table-wrap\">",
        );
        o.raw("<table class=\"idl-attributes\"><thead><tr>");
        o.head_cells(&["name", "type", "description"]);
        o.raw("</tr></thead>\n<tbody>\n");
        for a in &def.attributes {
            named_row(o, "attr-", &a.name);
            if a.readonly {
                o.label_in(" (", "idl_readonly", ")");
            }
            o.raw("</td>");
            type_and_doc(o, &a.ty, &a.doc, root);
        }
        o.raw("</tbody></table></div>");
    }
    o.raw("\n");
}
