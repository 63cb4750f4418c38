//! Line charts as PNG, for the figures the thesis draws as curves (Figure 2.12, Figure 5.11)
//! and for the accuracy/cost sweeps.
//!
//! Text is drawn with the bundled DejaVu Sans (`assets/fonts`, its licence beside it), so a
//! chart looks the same on every machine and needs no system fonts.

use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

/// One curve: its legend and its points, drawn joined in the order given.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// The legend.
    pub label: String,
    /// (x, y) points, joined in this order.
    pub points: Vec<(f64, f64)>,
}

/// A chart of curves over shared axes.
#[derive(Clone, Debug, PartialEq)]
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

/// An axis range, low to high.
type Span = (f64, f64);

static FONT: Once = Once::new();

/// `10^self` or `other`, the smaller.
trait Exp10Min {
    fn exp10_min(self, other: f64) -> f64;
}

impl Exp10Min for f64 {
    fn exp10_min(self, other: f64) -> f64 {
        10f64.powf(self).min(other)
    }
}

fn register_font() {
    FONT.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../assets/fonts/DejaVuSans.ttf");
        // The bundled font is a valid TrueType file; if it ever were not, text would be
        // missing from the chart, which the chart tests would see as a failed draw.
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, bytes);
    });
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
        /// The PNG file.
        path: std::path::PathBuf,
        /// The backend's message.
        message: String,
    },
}

impl Chart {
    /// The range of the data along x and y, padded so that no point sits on the frame.
    fn ranges(&self) -> Result<(Span, Span), PlotError> {
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

    /// Draw the chart into a PNG of `width` × `height` pixels at `path`.
    pub fn write_png(&self, path: &Path, width: u32, height: u32) -> Result<(), PlotError> {
        register_font();
        let ranges = self.ranges()?;
        let corner = self.legend_corner(ranges);
        // plotters' error is generic over its backend: kept as its message.
        let err = |e: &dyn std::fmt::Display| PlotError::Draw {
            path: path.to_path_buf(),
            message: e.to_string(),
        };
        let root = BitMapBackend::new(path, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        match (self.log_x, self.log_y) {
            (false, false) => self.draw(
                &root,
                ranges.0 .0..ranges.0 .1,
                ranges.1 .0..ranges.1 .1,
                corner,
            ),
            (true, false) => self.draw(
                &root,
                (ranges.0 .0..ranges.0 .1).log_scale(),
                ranges.1 .0..ranges.1 .1,
                corner,
            ),
            (false, true) => self.draw(
                &root,
                ranges.0 .0..ranges.0 .1,
                (ranges.1 .0..ranges.1 .1).log_scale(),
                corner,
            ),
            (true, true) => self.draw(
                &root,
                (ranges.0 .0..ranges.0 .1).log_scale(),
                (ranges.1 .0..ranges.1 .1).log_scale(),
                corner,
            ),
        }
        .map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))
    }

    /// The corner of the plot farthest from the data, for the legend: the one whose quarter
    /// (in axis coordinates, log where the axis is) holds the fewest curve samples.
    fn legend_corner(&self, (xs, ys): (Span, Span)) -> SeriesLabelPosition {
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
            SeriesLabelPosition::LowerLeft,
            SeriesLabelPosition::LowerRight,
            SeriesLabelPosition::UpperLeft,
            SeriesLabelPosition::UpperRight,
        ];
        let best = (0..4)
            .min_by_key(|&i| (counts[i], [3, 2, 1, 0][i]))
            .unwrap_or(3);
        corners[best].clone()
    }

    fn draw<X, Y>(
        &self,
        root: &DrawingArea<BitMapBackend, plotters::coord::Shift>,
        x: X,
        y: Y,
        corner: SeriesLabelPosition,
    ) -> Result<(), Box<dyn std::error::Error + '_>>
    where
        X: plotters::coord::ranged1d::AsRangedCoord<Value = f64>,
        Y: plotters::coord::ranged1d::AsRangedCoord<Value = f64>,
        X::CoordDescType: plotters::coord::ranged1d::ValueFormatter<f64>,
        Y::CoordDescType: plotters::coord::ranged1d::ValueFormatter<f64>,
    {
        let mut chart = ChartBuilder::on(root)
            .caption(&self.title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(x, y)?;
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style(("sans-serif", 13))
            .x_label_formatter(&|v| tick(*v))
            .y_label_formatter(&|v| tick(*v))
            .draw()?;
        for (i, s) in self.series.iter().enumerate() {
            let colour = Palette99::pick(i).to_rgba();
            chart
                .draw_series(LineSeries::new(
                    s.points.iter().copied(),
                    colour.stroke_width(2),
                ))?
                .label(&s.label)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2))
                });
            chart.draw_series(s.points.iter().map(|&p| Circle::new(p, 3, colour.filled())))?;
        }
        chart
            .configure_series_labels()
            .position(corner)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 13))
            .draw()?;
        Ok(())
    }
}

/// A tick label: whole numbers without a fraction (up to 1e6), powers of ten from 1e6 on as
/// 1e7, other large or small values with 3 significant digits.
fn tick(v: f64) -> String {
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
    fn draws_a_png_with_ink_on_it() {
        let dir = tempfile::tempdir().unwrap();
        for log in [false, true] {
            let path = dir.path().join(format!("c{log}.png"));
            chart(log, vec![(1.0, 2.0), (10.0, 40.0), (100.0, 3.0)])
                .write_png(&path, 320, 240)
                .unwrap();
            let img = image::open(&path).unwrap().to_rgb8();
            assert_eq!(img.dimensions(), (320, 240));
            // Not blank: text and curve leave dark pixels.
            let dark = img
                .pixels()
                .filter(|p| p.0.iter().all(|&c| c < 100))
                .count();
            assert!(dark > 200, "{dark} dark pixels");
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
    fn refuses_bad_values_without_writing() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("c.png");
        assert!(chart(true, vec![(0.0, 1.0)])
            .write_png(&path, 100, 100)
            .is_err());
        assert!(chart(false, vec![(f64::NAN, 1.0)])
            .write_png(&path, 100, 100)
            .is_err());
        assert!(!path.exists());
    }
}
