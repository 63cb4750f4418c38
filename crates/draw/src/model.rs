//! The three models of the one processor (docs/rendering.md): `cycle` and `word` are the
//! hardware (`rtl-model`), bit for bit equal; `float` is the exact geometry they are measured
//! against ([`crate::float`]).

use std::fmt;
use std::str::FromStr;

/// A model of the processor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Model {
    /// Bit-serial, clock by clock, bit-sliced (`rtl_model::CycleArray`).
    Cycle,
    /// One word per pixel, no clock (`rtl_model::WordArray`, or its plane words reduced to
    /// depth intervals where only the image matters).
    Word,
    /// Exact f64 geometry of the same planes: the reference, not hardware.
    Float,
}

impl Model {
    /// Every model, hardware first.
    pub const ALL: [Model; 3] = [Model::Cycle, Model::Word, Model::Float];

    /// The model's name on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            Model::Cycle => "cycle",
            Model::Word => "word",
            Model::Float => "float",
        }
    }

    /// One line on what the model is, for help texts.
    pub fn summary(self) -> &'static str {
        match self {
            Model::Cycle => "Bit-serial, clock by clock, bit-sliced",
            Model::Word => "One word per pixel, no clock",
            Model::Float => "Exact f64 geometry of the same planes: the reference, not hardware",
        }
    }

    /// Whether the model is the processor (clocks and words), not the reference.
    pub fn is_hardware(self) -> bool {
        self != Model::Float
    }
}

impl fmt::Display for Model {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A model name that is none of csgpix's.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown model `{name}`: cycle, word or float")]
pub struct UnknownModel {
    /// The name given.
    pub name: String,
}

impl FromStr for Model {
    type Err = UnknownModel;

    fn from_str(s: &str) -> Result<Model, UnknownModel> {
        Model::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| UnknownModel { name: s.into() })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_parse_back() {
        for m in Model::ALL {
            assert_eq!(m.name().parse::<Model>(), Ok(m));
            assert_eq!(m.to_string(), m.name());
        }
        assert!("Cycle".parse::<Model>().is_err());
        assert!(Model::Word.is_hardware() && !Model::Float.is_hardware());
    }
}
