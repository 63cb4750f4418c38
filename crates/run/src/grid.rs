//! The grid a job voxelizes on (docs/voxelization.md): how many voxels (`res`), or their
//! side (`voxel`), the padding, the sampling and the region, as data; the command line's
//! `--res`, `--voxel`, `--pad`, `--sampling`, `--bounds` and Python's keyword arguments.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use csgpix_voxel::sampled::Loaded;
use csgpix_voxel::{Grid, GridSpec, Sampling};

named!(Sampling: "sampling" {
    Sampling::Centre => "centre": "A voxel is inside when its centre is inside the solid",
    Sampling::Slab => "slab": "A voxel is inside a primitive when its segment along Z meets it (§4.4)",
} aliases { "center" => Sampling::Centre });

/// The grid options of a job, beside its resolution: `Default` is the documented defaults
/// (no voxel side, no padding, centre sampling, the scene's bounds).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct GridOptions {
    /// N or NXxNYxNZ voxels (`--res`).
    #[serde(with = "crate::named::by_text_opt")]
    pub res: Option<Resolution>,
    /// Instead of `res`: cubic voxels of this side, scene units (`--voxel`).
    pub voxel: Option<f64>,
    /// Empty voxels added on every side (`--pad`).
    pub pad: usize,
    /// Which depths of a voxel's ray classify it (`--sampling`).
    #[serde(with = "crate::named::by_name")]
    pub sampling: Sampling,
    /// The region, X0,Y0,Z0 and X1,Y1,Z1, scene units (`--bounds`; None: the scene's).
    pub bounds: Option<([f64; 3], [f64; 3])>,
}

impl GridOptions {
    /// The grid spec of these options (before bounds).
    pub fn spec(&self) -> GridSpec {
        grid_spec(self.res, self.voxel, self.pad)
    }

    /// The region asked for, as vectors.
    pub fn region(&self) -> Option<(DVec3, DVec3)> {
        self.bounds
            .map(|(a, b)| (DVec3::from_array(a), DVec3::from_array(b)))
    }

    /// The grid over the region, or over `scene`'s bounds.
    pub fn grid(&self, scene: &Loaded) -> Result<Grid, csgpix_voxel::Error> {
        scene.grid_over(&self.spec(), self.region())
    }

    /// Whether any option beside the resolution and sampling was given (they apply to
    /// scenes only).
    pub fn any(&self) -> bool {
        self.voxel.is_some() || self.pad > 0 || self.bounds.is_some()
    }
}

/// The grid spec of cubic voxels of side `voxel` if given, else of `res` (`--res`), with
/// `pad` empty voxels on every side (`--pad`); the Python binding's `res`, `voxel`, `pad`.
pub fn grid_spec(res: Option<Resolution>, voxel: Option<f64>, pad: usize) -> GridSpec {
    let spec = match (voxel, res) {
        (Some(v), _) => GridSpec {
            voxel: Some(v),
            ..GridSpec::default()
        },
        (None, Some(r)) => r.spec(),
        (None, None) => GridSpec::default(),
    };
    GridSpec { pad, ..spec }
}

/// `--res`: how many voxels, as binvox, OpenVDB and trimesh count them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Resolution {
    /// `N`: N cubic voxels along the bounds' longest side, the other sides covered by as
    /// many (the grid centred on the bounds); a cube's bounds get N×N×N over themselves.
    Longest(usize),
    /// `NXxNYxNZ`: voxels along X, Y and Z over the bounds (voxels need not be cubic).
    Axes([usize; 3]),
}

impl Resolution {
    /// The grid spec of this resolution (before `--pad`).
    pub fn spec(self) -> GridSpec {
        match self {
            Resolution::Longest(n) => GridSpec {
                longest: Some(n),
                ..GridSpec::default()
            },
            Resolution::Axes(dims) => GridSpec {
                res: Some(dims),
                ..GridSpec::default()
            },
        }
    }
}

/// `--res`: N (the longest side) or NXxNYxNZ, each 1..=65536.
pub fn parse_res(s: &str) -> crate::error::Parsed<Resolution> {
    let n = |v: &str| v.trim().parse::<usize>().map_err(|e| format!("{v:?}: {e}"));
    let parts: Vec<&str> = s.split(['x', 'X']).collect();
    let res = match parts[..] {
        [a] => Resolution::Longest(n(a)?),
        [a, b, c] => Resolution::Axes([n(a)?, n(b)?, n(c)?]),
        _ => return Err("expected N or NXxNYxNZ, e.g. 64 or 64x64x32".into()),
    };
    let sides = match res {
        Resolution::Longest(n) => vec![n],
        Resolution::Axes(dims) => dims.to_vec(),
    };
    if sides.iter().any(|&d| d == 0 || d > 65536) {
        return Err(crate::error::BadValue(format!(
            "{s}: each side must be 1..=65536"
        )));
    }
    Ok(res)
}

impl std::fmt::Display for Resolution {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Resolution::Longest(n) => write!(f, "{n}"),
            Resolution::Axes([x, y, z]) => write!(f, "{x}x{y}x{z}"),
        }
    }
}

impl std::str::FromStr for Resolution {
    type Err = crate::error::BadValue;
    fn from_str(s: &str) -> crate::error::Parsed<Resolution> {
        parse_res(s)
    }
}

/// `--bounds`: X0,Y0,Z0,X1,Y1,Z1, finite, each side positive and not degenerate.
pub fn parse_bounds(s: &str) -> crate::error::Parsed<(DVec3, DVec3)> {
    let v: Vec<f64> = s
        .split(',')
        .map(|x| x.trim().parse::<f64>().map_err(|e| format!("{x:?}: {e}")))
        .collect::<Result<_, _>>()?;
    let [x0, y0, z0, x1, y1, z1] = v[..] else {
        return Err("expected X0,Y0,Z0,X1,Y1,Z1".into());
    };
    let (lo, hi) = (DVec3::new(x0, y0, z0), DVec3::new(x1, y1, z1));
    let extent = hi - lo;
    if !(lo.is_finite() && hi.is_finite()) {
        return Err("every bound must be a finite number".into());
    }
    if !extent.is_finite() {
        return Err(crate::error::BadValue(format!(
            "the extent {extent} overflows: bounds must be within ±1e307"
        )));
    }
    if extent.min_element() <= 0.0 {
        return Err("each X1, Y1, Z1 must be greater than its X0, Y0, Z0".into());
    }
    let (side, min) = (extent.min_element(), csgpix_scene::grid::MIN_EXTENT);
    if side < min {
        return Err(format!("degenerate extent: a side is {side:e}, under {min:e}").into());
    }
    Ok((lo, hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_resolution_prints_as_it_parses() {
        for s in ["64", "64x32x16"] {
            assert_eq!(s.parse::<Resolution>().unwrap().to_string(), s);
        }
        assert!("0".parse::<Resolution>().is_err());
        assert!("1x2".parse::<Resolution>().is_err());
    }

    #[test]
    fn grid_options_go_through_json_unchanged() {
        let o = GridOptions {
            res: Some(Resolution::Axes([4, 5, 6])),
            pad: 2,
            sampling: Sampling::Slab,
            bounds: Some(([-1.0, -2.0, -3.0], [1.0, 2.0, 3.0])),
            ..GridOptions::default()
        };
        let text = serde_json::to_string(&o).unwrap();
        assert_eq!(serde_json::from_str::<GridOptions>(&text).unwrap(), o);
        assert_eq!(
            serde_json::from_str::<GridOptions>("{}").unwrap(),
            GridOptions::default()
        );
    }
}
