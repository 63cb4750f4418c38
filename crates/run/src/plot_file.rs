//! TRANSITION (issue 39): `throughput --plots` still draws its charts to files here, with
//! plotters, until its job takes a [`Charts`](crate::plot::Charts) as `study` does; then
//! this module (and plotters in crates/run) goes. The binary's drawing (`src/cli/plot.rs`)
//! is the same.

use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

use crate::plot::{tick, Chart, Corner, PlotError};

static FONT: Once = Once::new();

fn register_font() {
    FONT.call_once(|| {
        let bytes: &'static [u8] = crate::plot::FONT_TTF;
        // The bundled font is a valid TrueType file; if it ever were not, text would be
        // missing from the chart, which the chart tests would see as a failed draw.
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, bytes);
    });
}

fn position(c: Corner) -> SeriesLabelPosition {
    match c {
        Corner::LowerLeft => SeriesLabelPosition::LowerLeft,
        Corner::LowerRight => SeriesLabelPosition::LowerRight,
        Corner::UpperLeft => SeriesLabelPosition::UpperLeft,
        Corner::UpperRight => SeriesLabelPosition::UpperRight,
    }
}

impl Chart {
    /// Draw the chart into a PNG of `width` × `height` pixels at `path`.
    pub fn write_png(&self, path: &Path, width: u32, height: u32) -> Result<(), PlotError> {
        register_font();
        let ranges = self.ranges()?;
        let corner = position(self.legend_corner(ranges));
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
