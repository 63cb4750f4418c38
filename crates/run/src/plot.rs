//! Line charts as data, for the figures the thesis draws as curves (Figure 2.12, Figure 5.11)
//! and for the accuracy/cost sweeps of `study`: the curves, the axes, the titles, the ranges
//! and the legend's corner. Drawing them is not the run layer's: a job that writes charts
//! takes a [`Charts`] (the binary's draws with plotters, `src/cli/plot.rs`) and stages the
//! PNG bytes it returns with its other files.

use serde::Serialize;

/// One curve: its legend and its points, drawn joined in the order given.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Series {
    /// The legend.
    pub label: String,
    /// (x, y) points, joined in this order.
    pub points: Vec<(f64, f64)>,
}

/// A chart of curves over shared axes.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Chart {
    /// The title above the plot.
    pub title: String,
    /// The X axis's label.
    pub x_label: String,
    /// The Y axis's label.
    pub y_label: String,
    /// A logarithmic X axis (every x must then be > 0).
    pub log_x: bool,
    /// A logarithmic Y axis (every y must then be > 0).
    pub log_y: bool,
    /// The curves.
    pub series: Vec<Series>,
}

/// The font of every chart's text: DejaVu Sans, bundled (`assets/fonts`, its licence beside
/// it), so a chart needs no system fonts.
pub const FONT_TTF: &[u8] = include_bytes!("../assets/fonts/DejaVuSans.ttf");

/// An axis range, low to high.
pub type Span = (f64, f64);

/// A corner of the plot, where the legend goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Corner {
    /// Bottom left.
    LowerLeft,
    /// Bottom right.
    LowerRight,
    /// Top left.
    UpperLeft,
    /// Top right.
    UpperRight,
}

/// What draws a chart as a PNG image: the binary's implementation draws with plotters and
/// the bundled DejaVu Sans, so a chart looks the same on every machine.
pub trait Charts: Sync {
    /// The chart drawn into a PNG of `width` × `height` pixels, as the file's bytes.
    fn png(&self, chart: &Chart, width: u32, height: u32) -> Result<Vec<u8>, PlotError>;
}

/// A chart that could not be drawn.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlotError {
    /// A point is NaN or infinite.
    #[error("{title}: a point is not finite")]
    NotFinite {
        /// The chart's title.
        title: String,
    },
    /// A value on a log axis is zero or negative.
    #[error("{title}: a value on a log axis is not positive")]
    NotPositive {
        /// The chart's title.
        title: String,
    },
    /// The backend could not draw or write the file.
    #[error("{}: {message}", csgpix_output::OneLine(path.display()))]
    Draw {
        /// The PNG file (or, drawn in memory, the chart's title).
        path: std::path::PathBuf,
        /// The backend's message.
        message: String,
    },
}

/// `10^self` or `other`, the smaller.
trait Exp10Min {
    fn exp10_min(self, other: f64) -> f64;
}

impl Exp10Min for f64 {
    fn exp10_min(self, other: f64) -> f64 {
        10f64.powf(self).min(other)
    }
}

impl Chart {
    /// The range of the data along x and y, padded so that no point sits on the frame; an
    /// error where a point is not finite or a log axis has a value that is not positive.
    pub fn ranges(&self) -> Result<(Span, Span), PlotError> {
        let pts = || self.series.iter().flat_map(|s| s.points.iter().copied());
        if pts().any(|(x, y)| !x.is_finite() || !y.is_finite()) {
            return Err(PlotError::NotFinite {
                title: self.title.clone(),
            });
        }
        if (self.log_x && pts().any(|(x, _)| x <= 0.0))
            || (self.log_y && pts().any(|(_, y)| y <= 0.0))
        {
            return Err(PlotError::NotPositive {
                title: self.title.clone(),
            });
        }
        let span = |v: Vec<f64>, log: bool| -> Span {
            let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            if !lo.is_finite() {
                return if log { (1.0, 10.0) } else { (0.0, 1.0) };
            }
            if log {
                // Down to the decade below, so the lowest curve has a labelled tick under it.
                (lo.log10().floor().exp10_min(lo / 1.5), hi * 1.5)
            } else {
                let pad = ((hi - lo) * 0.05).max(hi.abs() * 0.05).max(1e-12);
                (lo - pad, hi + pad)
            }
        };
        Ok((
            span(pts().map(|p| p.0).collect(), self.log_x),
            span(pts().map(|p| p.1).collect(), self.log_y),
        ))
    }

    /// The corner of the plot farthest from the data, for the legend: the one whose quarter
    /// (in axis coordinates, log where the axis is) holds the fewest curve samples.
    pub fn legend_corner(&self, (xs, ys): (Span, Span)) -> Corner {
        let norm = |v: f64, (lo, hi): Span, log: bool| {
            if log {
                (v.ln() - lo.ln()) / (hi.ln() - lo.ln())
            } else {
                (v - lo) / (hi - lo)
            }
        };
        let mut counts = [0usize; 4];
        for s in &self.series {
            for w in s.points.windows(2) {
                for k in 0..=16 {
                    let t = k as f64 / 16.0;
                    let p = |a: f64, b: f64, r: Span, log: bool| {
                        let (a, b) = (norm(a, r, log), norm(b, r, log));
                        a + (b - a) * t
                    };
                    let x = p(w[0].0, w[1].0, xs, self.log_x);
                    let y = p(w[0].1, w[1].1, ys, self.log_y);
                    let (right, up) = (x > 0.55, y > 0.7);
                    if (x < 0.45 || right) && (y < 0.3 || up) {
                        counts[(right as usize) + 2 * (up as usize)] += 1;
                    }
                }
            }
        }
        let corners = [
            Corner::LowerLeft,
            Corner::LowerRight,
            Corner::UpperLeft,
            Corner::UpperRight,
        ];
        let best = (0..4)
            .min_by_key(|&i| (counts[i], [3, 2, 1, 0][i]))
            .unwrap_or(3);
        corners[best]
    }
}

/// A tick label: whole numbers without a fraction (up to 1e6), powers of ten from 1e6 on as
/// 1e7, other large or small values with 3 significant digits.
pub fn tick(v: f64) -> String {
    let a = v.abs();
    if a >= 1e6 || (a > 0.0 && a < 1e-3) {
        let s = format!("{v:.2e}");
        // 1.00e7 -> 1e7, 2.50e6 -> 2.5e6
        let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
        let m = m.trim_end_matches('0').trim_end_matches('.');
        format!("{m}e{e}")
    } else if (v - v.round()).abs() < 1e-9 * a.max(1.0) {
        format!("{v:.0}")
    } else {
        let digits = (2 - a.log10().floor() as i32).max(0) as usize;
        format!("{v:.digits$}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chart(log: bool, points: Vec<(f64, f64)>) -> Chart {
        Chart {
            title: "t".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            log_x: log,
            log_y: log,
            series: vec![Series {
                label: "a".into(),
                points,
            }],
        }
    }

    #[test]
    fn tick_labels_are_short() {
        assert_eq!(tick(100_000_000.0), "1e8");
        assert_eq!(tick(2_500_000.0), "2.5e6");
        assert_eq!(tick(1000.0), "1000");
        assert_eq!(tick(0.5), "0.500");
        assert_eq!(tick(12.34), "12.3");
    }

    #[test]
    fn refuses_bad_values() {
        let e = chart(true, vec![(0.0, 1.0)]).ranges().unwrap_err();
        assert_eq!(e.to_string(), "t: a value on a log axis is not positive");
        let e = chart(false, vec![(f64::NAN, 1.0)]).ranges().unwrap_err();
        assert_eq!(e.to_string(), "t: a point is not finite");
    }

    #[test]
    fn ranges_pad_the_data_and_reach_the_decade_below_on_log_axes() {
        let (x, y) = chart(false, vec![(0.0, 10.0), (10.0, 20.0)])
            .ranges()
            .unwrap();
        assert_eq!((x, y), ((-0.5, 10.5), (9.0, 21.0)));
        let (x, _) = chart(true, vec![(3.0, 1.0), (30.0, 2.0)]).ranges().unwrap();
        assert_eq!(x, (1.0, 45.0));
    }

    /// A curve rising from the lower left to the upper right leaves the other two corners
    /// free; of those the upper left is preferred.
    #[test]
    fn the_legend_goes_where_the_curves_are_not() {
        let c = chart(false, vec![(0.0, 0.0), (1.0, 1.0)]);
        let r = c.ranges().unwrap();
        assert_eq!(c.legend_corner(r), Corner::UpperLeft);
        let c = chart(false, vec![(0.0, 1.0), (1.0, 0.0)]);
        let r = c.ranges().unwrap();
        assert_eq!(c.legend_corner(r), Corner::UpperRight);
    }
}
