//! Data-type and interface-type names: one canonical spelling per type.
//!
//! The same IDL type is written `RTC::TimedLong`, `TimedLong` (spec appendix 5.3 lists the basic
//! types without module) or as a repository id `IDL:RTC/TimedLong:1.0`. Cross-links treat these as
//! one type, keyed by the canonical `Module::Name` form.

/// Types of OpenRTM's `RTC` module (BasicDataType.idl, ExtendedDataTypes.idl,
/// InterfaceDataTypes.idl) that profiles often write without the module.
const RTC_MODULE_TYPES: &[&str] = &[
    // BasicDataType.idl (spec 5.3)
    "TimedState",
    "TimedShort",
    "TimedLong",
    "TimedUShort",
    "TimedULong",
    "TimedFloat",
    "TimedDouble",
    "TimedChar",
    "TimedWChar",
    "TimedBoolean",
    "TimedOctet",
    "TimedString",
    "TimedWString",
    "TimedShortSeq",
    "TimedLongSeq",
    "TimedUShortSeq",
    "TimedULongSeq",
    "TimedFloatSeq",
    "TimedDoubleSeq",
    "TimedCharSeq",
    "TimedWCharSeq",
    "TimedBooleanSeq",
    "TimedOctetSeq",
    "TimedStringSeq",
    "TimedWStringSeq",
    // ExtendedDataTypes.idl
    "TimedRGBColour",
    "TimedPoint2D",
    "TimedVector2D",
    "TimedPose2D",
    "TimedVelocity2D",
    "TimedAcceleration2D",
    "TimedPoseVel2D",
    "TimedSize2D",
    "TimedGeometry2D",
    "TimedCovariance2D",
    "TimedPointCovariance2D",
    "TimedCarlike",
    "TimedSpeedHeading2D",
    "TimedPoint3D",
    "TimedVector3D",
    "TimedOrientation3D",
    "TimedPose3D",
    "TimedVelocity3D",
    "TimedAngularVelocity3D",
    "TimedAcceleration3D",
    "TimedAngularAcceleration3D",
    "TimedPoseVel3D",
    "TimedSize3D",
    "TimedGeometry3D",
    "TimedCovariance3D",
    "TimedSpeedHeading3D",
    "TimedOAP",
    "ActArrayState",
    "BumperGeometry",
    "CameraImage",
    "CameraInfo",
    "Fiducials",
    "GPSData",
    "GripperState",
    "INSData",
    "LimbState",
    "Hypotheses2D",
    "Hypotheses3D",
    "MulticameraImages",
    "Path2D",
    "Path3D",
    "PointCloud",
    "PanTiltAngles",
    "PanTiltState",
    "RangeData",
    "IntensityData",
    "TimedEnum",
    // InterfaceDataTypes.idl
    "OGMap",
];

/// The IDL files OpenRTM-aist installs (`rtm/idl`): projects often keep copies of them.
pub const OPENRTM_IDL_FILES: &[&str] = &[
    "BasicDataType.idl",
    "CameraCommonInterface.idl",
    "DataPort.idl",
    "DataPortUDP.idl",
    "ExtendedDataTypes.idl",
    "Img.idl",
    "InterfaceDataTypes.idl",
    "Manager.idl",
    "ManipulatorCommonInterface_Common.idl",
    "ManipulatorCommonInterface_DataTypes.idl",
    "ManipulatorCommonInterface_Middle.idl",
    "OpenRTM.idl",
    "RTC.idl",
    "SDOPackage.idl",
    "SDOPackage11.idl",
    "SharedMemory.idl",
];

/// Whether the file at `path` (its name, any folder) is a copy of one of OpenRTM's own IDL
/// files ([`OPENRTM_IDL_FILES`]).
pub fn is_openrtm_idl_file(path: &str) -> bool {
    // Not `idl::pp::file_name`: `types` stays below `idl` (no import circle).
    let name = path.rsplit(['/', '\\']).next().unwrap_or(path);
    OPENRTM_IDL_FILES.contains(&name)
}

/// Whether `name` (any spelling) is one of the types of OpenRTM's own `RTC` module, which an
/// installation of OpenRTM brings (a project that does not copy its IDL still uses them).
pub fn is_openrtm_type(name: &str) -> bool {
    canonical_type(name)
        .strip_prefix("RTC::")
        .is_some_and(|short| RTC_MODULE_TYPES.contains(&short))
}

/// The canonical spelling of a data or interface type name.
///
/// - `IDL:RTC/TimedLong:1.0` → `RTC::TimedLong` (repository id: `/` separates modules, the
///   trailing `:version` is dropped);
/// - `TimedLong` → `RTC::TimedLong` for the types of OpenRTM's `RTC` module;
/// - surrounding white space is trimmed and a leading `::` removed; anything else is kept as is.
pub fn canonical_type(name: &str) -> String {
    let mut s = name.trim();
    let owned;
    if let Some(rest) = s.strip_prefix("IDL:") {
        let body = match rest.rfind(':') {
            Some(i) => &rest[..i],
            None => rest,
        };
        owned = body.replace('/', "::");
        s = &owned;
    }
    let s = s.strip_prefix("::").unwrap_or(s).trim();
    if !s.contains("::") && RTC_MODULE_TYPES.contains(&s) {
        return format!("RTC::{s}");
    }
    s.to_string()
}

/// The last `::` segment of a type (`RTC::TimedLong` → `TimedLong`), for compact labels.
pub fn short_name(canonical: &str) -> &str {
    canonical.rsplit("::").next().unwrap_or(canonical)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spellings_of_one_type_agree_and_user_types_are_kept() {
        for (written, canonical) in [
            ("RTC::TimedLong", "RTC::TimedLong"),
            ("TimedLong", "RTC::TimedLong"),
            ("IDL:RTC/TimedLong:1.0", "RTC::TimedLong"),
            ("  ::RTC::TimedLong ", "RTC::TimedLong"),
            ("Img::TimedCameraImage", "Img::TimedCameraImage"),
            ("MyType", "MyType"),
            ("IDL:Img/TimedCameraImage:1.0", "Img::TimedCameraImage"),
            ("IDL:a/b/C:2.1", "a::b::C"),
        ] {
            assert_eq!(canonical_type(written), canonical, "{written}");
        }
    }

    #[test]
    fn short_names() {
        assert_eq!(short_name("RTC::TimedLong"), "TimedLong");
        assert_eq!(short_name("Plain"), "Plain");
    }
}
