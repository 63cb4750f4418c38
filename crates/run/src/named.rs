//! An option's closed set of values (`--route runs`, `route="runs"`): each value with its one
//! spelling, shared by the command line (the binary builds its value parsers and `--help`
//! lists from [`Named::VALUES`]) and Python (keyword arguments parsed by [`parse`]).

use crate::error::{BadValue, Parsed};

/// A closed set of values with names and one line of help each.
pub trait Named: Copy + PartialEq + Send + Sync + 'static {
    /// What a value is of, as messages say it (`route`, `view`).
    const WHAT: &'static str;
    /// Every value: the value, its name, its help.
    const VALUES: &'static [(Self, &'static str, &'static str)];
    /// Other spellings accepted for a value (`center` for `centre`).
    const ALIASES: &'static [(&'static str, Self)] = &[];

    /// The value's name.
    fn name(self) -> &'static str {
        Self::VALUES
            .iter()
            .find(|v| v.0 == self)
            .map_or("?", |v| v.1)
    }
}

/// The value named `s` (or an alias), else a message listing the names:
/// `route "x": `runs`, `intervals`, `array``.
pub fn parse<T: Named>(s: &str) -> Parsed<T> {
    let by_name = T::VALUES.iter().find(|v| v.1 == s).map(|v| v.0);
    let by_alias = || T::ALIASES.iter().find(|a| a.0 == s).map(|a| a.1);
    by_name.or_else(by_alias).ok_or_else(|| {
        let names: Vec<String> = T::VALUES.iter().map(|v| format!("`{}`", v.1)).collect();
        BadValue(format!("{} {s:?}: {}", T::WHAT, names.join(", ")))
    })
}

/// Declares the [`Named`] values of a type, and for the run layer's own enums (`own`) also
/// `FromStr`, `Display` and serde by name.
macro_rules! named {
    ($t:ty: $what:literal { $($v:expr => $name:literal: $help:literal),+ $(,)? }
     $(aliases { $($a:literal => $av:expr),+ $(,)? })?) => {
        impl $crate::named::Named for $t {
            const WHAT: &'static str = $what;
            const VALUES: &'static [(Self, &'static str, &'static str)] =
                &[$(($v, $name, $help)),+];
            $(const ALIASES: &'static [(&'static str, Self)] = &[$(($a, $av)),+];)?
        }
    };
    (own $t:ty: $($rest:tt)+) => {
        named!($t: $($rest)+);
        impl std::str::FromStr for $t {
            type Err = $crate::error::BadValue;
            fn from_str(s: &str) -> $crate::error::Parsed<Self> {
                $crate::named::parse(s)
            }
        }
        impl std::fmt::Display for $t {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str($crate::named::Named::name(*self))
            }
        }
        impl serde::Serialize for $t {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.serialize_str($crate::named::Named::name(*self))
            }
        }
        impl<'de> serde::Deserialize<'de> for $t {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                let s = <std::borrow::Cow<'de, str>>::deserialize(d)?;
                $crate::named::parse(&s).map_err(serde::de::Error::custom)
            }
        }
    };
}

/// serde by name for a [`Named`] type that is not the run layer's own (`#[serde(with =
/// "crate::named::by_name")]`): the library's enums a job holds (`Model`, `Equations`).
pub mod by_name {
    use super::Named;

    /// The value's name.
    pub fn serialize<T: Named, S: serde::Serializer>(v: &T, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(v.name())
    }

    /// The value of a name.
    pub fn deserialize<'de, T: Named, D: serde::Deserializer<'de>>(d: D) -> Result<T, D::Error> {
        use serde::Deserialize;
        let s = <std::borrow::Cow<'de, str>>::deserialize(d)?;
        super::parse(&s).map_err(serde::de::Error::custom)
    }
}

/// serde by `Display` and `FromStr` (`#[serde(with = "crate::named::by_text")]`): values
/// with a textual form of their own, as the command line spells them (`10/10/11`).
pub mod by_text {
    use std::fmt::Display;
    use std::str::FromStr;

    /// The value as text.
    pub fn serialize<T: Display, S: serde::Serializer>(v: &T, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(v)
    }

    /// The value of a text.
    pub fn deserialize<'de, T, D>(d: D) -> Result<T, D::Error>
    where
        T: FromStr,
        T::Err: Display,
        D: serde::Deserializer<'de>,
    {
        use serde::Deserialize;
        let s = <std::borrow::Cow<'de, str>>::deserialize(d)?;
        s.parse().map_err(serde::de::Error::custom)
    }
}

/// serde of an `Option` by `Display` and `FromStr` (`#[serde(with =
/// "crate::named::by_text_opt")]`): None as null.
pub mod by_text_opt {
    use std::fmt::Display;
    use std::str::FromStr;

    /// The value as text, or null.
    pub fn serialize<T: Display, S: serde::Serializer>(
        v: &Option<T>,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        match v {
            Some(v) => s.collect_str(v),
            None => s.serialize_none(),
        }
    }

    /// The value of a text, or None for null.
    pub fn deserialize<'de, T, D>(d: D) -> Result<Option<T>, D::Error>
    where
        T: FromStr,
        T::Err: Display,
        D: serde::Deserializer<'de>,
    {
        use serde::Deserialize;
        let s = <Option<std::borrow::Cow<'de, str>>>::deserialize(d)?;
        s.map(|s| s.parse().map_err(serde::de::Error::custom))
            .transpose()
    }
}

named!(csgpix_draw::Model: "model" {
    csgpix_draw::Model::Cycle => "cycle": "Bit-serial, clock by clock, bit-sliced",
    csgpix_draw::Model::Word => "word": "One word per pixel, no clock",
    csgpix_draw::Model::Float => "float": "Exact f64 geometry of the same planes: the reference, not hardware",
});

named!(rtl_model::Equations: "equations" {
    rtl_model::Equations::Derived => "derived": "Minimized from the golden vectors (default)",
    rtl_model::Equations::Printed => "printed": "Exactly the thesis text, faults included",
});

named!(csgpix_draw::project::View: "view" {
    csgpix_draw::project::View::Top => "top": "Looking down −Z (x right, y up)",
    csgpix_draw::project::View::Front => "front": "Looking along +Y (x right, z up)",
    csgpix_draw::project::View::Iso => "iso": "Isometric, from (+1, −1, +1)",
});

#[cfg(test)]
mod tests {
    use super::*;
    use csgpix_draw::project::View;
    use csgpix_draw::Model;

    #[derive(Clone, Copy, Debug, PartialEq)]
    enum Colour {
        Red,
        Grey,
    }

    named!(own Colour: "colour" {
        Colour::Red => "red": "the first",
        Colour::Grey => "grey": "the second",
    } aliases { "gray" => Colour::Grey });

    #[test]
    fn every_value_parses_back_from_its_name() {
        for &(v, name, _) in Colour::VALUES {
            assert_eq!(parse::<Colour>(name), Ok(v));
            assert_eq!(v.to_string(), name);
        }
        for &(v, name, _) in Model::VALUES {
            assert_eq!(parse::<Model>(name), Ok(v));
            // The library's own spelling is the same.
            assert_eq!(name.parse::<Model>().ok(), Some(v));
        }
        assert_eq!(parse::<View>("front"), Ok(View::Front));
    }

    #[test]
    fn an_alias_parses_and_an_unknown_name_lists_the_names() {
        assert_eq!("gray".parse::<Colour>(), Ok(Colour::Grey));
        let e = "blue".parse::<Colour>().unwrap_err();
        assert_eq!(e.to_string(), "colour \"blue\": `red`, `grey`");
    }

    #[test]
    fn serde_goes_by_name() {
        assert_eq!(serde_json::to_string(&Colour::Grey).unwrap(), "\"grey\"");
        let back: Colour = serde_json::from_str("\"red\"").unwrap();
        assert_eq!(back, Colour::Red);
        assert!(serde_json::from_str::<Colour>("\"blue\"").is_err());
    }
}
