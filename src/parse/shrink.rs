//! Gives back the spare capacity of a parsed profile's vectors.
//!
//! The readers build every list by pushing, so a list of 5 ports holds room for 8, and the
//! per-attribute positions of each node ([`AttrPos`](crate::model::AttrPos)) room for up to
//! twice their entries. A profile stays in memory until the build ends, so at 10,000 profiles
//! the unused room is megabytes of peak memory (see book/src/performance.md). Only capacity
//! changes: the values, their order and so every output stay the same.

use crate::model::{AttrPos, Extras, Profile, Property};

fn extras(v: &mut Extras) {
    for e in v.iter_mut() {
        extras(&mut e.children);
    }
    v.shrink_to_fit();
}

/// The three lists a node with attributes has: their positions, its properties, its extras.
fn node(attr_pos: &mut AttrPos, properties: &mut Vec<Property>, extra: &mut Extras) {
    attr_pos.shrink_to_fit();
    properties.shrink_to_fit();
    extras(extra);
}

/// Shrinks every list of `p` to its length.
pub(crate) fn profile(p: &mut Profile) {
    p.attr_pos.shrink_to_fit();
    extras(&mut p.extra);
    let b = &mut p.basic_info;
    node(&mut b.attr_pos, &mut b.properties, &mut b.extra);
    for a in &mut p.actions {
        extras(&mut a.extra);
    }
    p.actions.shrink_to_fit();
    if let Some(cs) = &mut p.configuration_set {
        for c in &mut cs.configurations {
            node(&mut c.attr_pos, &mut c.properties, &mut c.extra);
        }
        cs.configurations.shrink_to_fit();
        extras(&mut cs.extra);
    }
    for d in &mut p.data_ports {
        node(&mut d.attr_pos, &mut d.properties, &mut d.extra);
    }
    p.data_ports.shrink_to_fit();
    for s in &mut p.service_ports {
        node(&mut s.attr_pos, &mut s.properties, &mut s.extra);
        for i in &mut s.interfaces {
            node(&mut i.attr_pos, &mut i.properties, &mut i.extra);
        }
        s.interfaces.shrink_to_fit();
    }
    p.service_ports.shrink_to_fit();
    p.parameters.shrink_to_fit();
    p.written_as.shrink_to_fit();
}

#[cfg(test)]
mod tests {
    use crate::parse::{self, Limits, SourceFormat};

    #[test]
    fn a_read_profile_holds_no_spare_capacity_and_the_same_values() {
        for (dir, format, file) in [
            ("Navigator", SourceFormat::Xml, "RTC.xml"),
            ("UsbCamera", SourceFormat::Yaml, "RTC.yaml"),
        ] {
            let path = format!("{}/examples/{dir}/{file}", env!("CARGO_MANIFEST_DIR"));
            let bytes = std::fs::read(path).unwrap();
            let limits = Limits::default();
            let p = parse::parse(format, &bytes, file, &limits).unwrap().profile;
            assert!(!p.data_ports.is_empty() && !p.basic_info.attr_pos.is_empty());
            assert_eq!(p.data_ports.capacity(), p.data_ports.len(), "{dir}");
            assert_eq!(p.actions.capacity(), p.actions.len(), "{dir}");
            assert_eq!(
                p.basic_info.attr_pos.capacity(),
                p.basic_info.attr_pos.len(),
                "{dir}"
            );
            for d in &p.data_ports {
                assert_eq!(d.attr_pos.capacity(), d.attr_pos.len(), "{dir}");
            }
            // The same values as the reader's own result, which had room to spare.
            let mut raw = match format {
                SourceFormat::Xml => parse::xml::parse(&bytes, file, &limits),
                SourceFormat::Yaml => parse::yaml::parse(&bytes, file, &limits),
            }
            .unwrap()
            .profile;
            raw.actions.sort_by_key(|a| a.kind);
            parse::dialect::annotate(&mut raw);
            let spare = raw.data_ports.capacity() - raw.data_ports.len()
                + raw.basic_info.attr_pos.capacity()
                - raw.basic_info.attr_pos.len()
                + raw
                    .data_ports
                    .iter()
                    .map(|d| d.attr_pos.capacity() - d.attr_pos.len())
                    .sum::<usize>();
            assert!(spare > 0, "{dir}: nothing to shrink");
            assert_eq!(raw, p, "{dir}");
        }
    }
}
