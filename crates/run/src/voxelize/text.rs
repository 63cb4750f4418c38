//! serde of the job's values that have a textual form on the command line: the depth word
//! (`10/10/11`), a blend (`max`, `sum:KS,KD`), the primitives' bindings
//! (`NAME=FILE[,threshold=T]`) and optional named values.

use serde::{Deserialize, Deserializer, Serializer};

/// Text from a deserializer, or an error.
fn text<'de, D: Deserializer<'de>>(d: D) -> Result<std::borrow::Cow<'de, str>, D::Error> {
    <std::borrow::Cow<'de, str>>::deserialize(d)
}

/// `--word`: `FRACTION/INTEGER/OVERFLOW`.
pub mod word {
    use super::*;
    use rtl_model::WordFormat;

    pub fn serialize<S: Serializer>(w: &WordFormat, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(&format_args!("{}/{}/{}", w.frac, w.int, w.ovf))
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<WordFormat, D::Error> {
        crate::array_args::parse_word(&text(d)?).map_err(serde::de::Error::custom)
    }
}

/// `--blend`: `max` or `sum:KS,KD`, or null.
pub mod blend {
    use super::*;
    use csgpix_voxel::blend::Union;

    pub fn serialize<S: Serializer>(u: &Option<Union>, s: S) -> Result<S::Ok, S::Error> {
        match u {
            None => s.serialize_none(),
            Some(Union::Max) => s.serialize_str("max"),
            Some(Union::Sum { ks, kd }) => s.collect_str(&format_args!("sum:{ks},{kd}")),
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Union>, D::Error> {
        let t = <Option<std::borrow::Cow<'de, str>>>::deserialize(d)?;
        t.map(|t| super::super::parse_blend(&t).map_err(serde::de::Error::custom))
            .transpose()
    }
}

/// `--prim`: each binding as `NAME=FILE[,threshold=T]`.
pub mod prims {
    use super::*;
    use csgpix_voxel::sampled::{parse_binding, Binding};
    use serde::ser::SerializeSeq;

    pub fn serialize<S: Serializer>(b: &[Binding], s: S) -> Result<S::Ok, S::Error> {
        let mut seq = s.serialize_seq(Some(b.len()))?;
        for b in b {
            let t = match b.threshold {
                Some(t) => format!("{}={},threshold={t}", b.name, b.file.display()),
                None => format!("{}={}", b.name, b.file.display()),
            };
            seq.serialize_element(&t)?;
        }
        seq.end()
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<Binding>, D::Error> {
        let texts = <Vec<String>>::deserialize(d)?;
        let each = texts.iter().map(|t| parse_binding(t));
        each.collect::<Result<_, _>>()
            .map_err(serde::de::Error::custom)
    }
}

/// An optional [`Named`](crate::named::Named) value by its name, or null.
pub mod opt_name {
    use super::*;
    use crate::named::Named;

    pub fn serialize<T: Named, S: Serializer>(v: &Option<T>, s: S) -> Result<S::Ok, S::Error> {
        match v {
            Some(v) => s.serialize_str(v.name()),
            None => s.serialize_none(),
        }
    }

    pub fn deserialize<'de, T: Named, D: Deserializer<'de>>(d: D) -> Result<Option<T>, D::Error> {
        let t = <Option<std::borrow::Cow<'de, str>>>::deserialize(d)?;
        t.map(|t| crate::named::parse(&t).map_err(serde::de::Error::custom))
            .transpose()
    }
}
