//! The charts of the run layer ([`csgpix_run::plot::Chart`]: curves, axes, titles, ranges,
//! the legend's corner) drawn as PNG with plotters, text in the bundled DejaVu Sans so a
//! chart looks the same on every machine and needs no system fonts.

use std::sync::Once;

use csgpix_run::plot::{tick, Chart, Charts, Corner, PlotError, FONT_TTF};
use plotters::prelude::*;

/// The command line's chart drawer.
#[derive(Debug, Clone, Copy, Default)]
pub struct Plotters;

/// A drawing area over an RGB buffer.
type Area<'a> = DrawingArea<BitMapBackend<'a>, plotters::coord::Shift>;

static FONT: Once = Once::new();

fn register_font() {
    FONT.call_once(|| {
        // The bundled font is a valid TrueType file; if it ever were not, text would be
        // missing from the chart, which the chart tests would see as a failed draw.
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, FONT_TTF);
    });
}

impl Charts for Plotters {
    fn png(&self, chart: &Chart, width: u32, height: u32) -> Result<Vec<u8>, PlotError> {
        register_font();
        let ranges = chart.ranges()?;
        let corner = position(chart.legend_corner(ranges));
        // plotters' error is generic over its backend: kept as its message.
        let err = |e: &dyn std::fmt::Display| PlotError::Draw {
            path: chart.title.clone().into(),
            message: e.to_string(),
        };
        let mut rgb = vec![0u8; width as usize * height as usize * 3];
        {
            let root = BitMapBackend::with_buffer(&mut rgb, (width, height)).into_drawing_area();
            root.fill(&WHITE).map_err(|e| err(&e))?;
            let ((x0, x1), (y0, y1)) = ranges;
            match (chart.log_x, chart.log_y) {
                (false, false) => draw(chart, &root, x0..x1, y0..y1, corner),
                (true, false) => draw(chart, &root, (x0..x1).log_scale(), y0..y1, corner),
                (false, true) => draw(chart, &root, x0..x1, (y0..y1).log_scale(), corner),
                (true, true) => draw(
                    chart,
                    &root,
                    (x0..x1).log_scale(),
                    (y0..y1).log_scale(),
                    corner,
                ),
            }
            .map_err(|e| err(&e))?;
            root.present().map_err(|e| err(&e))?;
        }
        encode(&rgb, width, height).map_err(|e| err(&e))
    }
}

/// The RGB pixels as a PNG file's bytes, encoded as plotters' bitmap backend saves a file
/// (its image crate's PNG encoder: png 0.17, fast compression, adaptive filters), so a chart
/// has the bytes it had when plotters wrote it.
fn encode(rgb: &[u8], width: u32, height: u32) -> Result<Vec<u8>, png017::EncodingError> {
    let mut bytes = vec![];
    let mut enc = png017::Encoder::new(&mut bytes, width, height);
    enc.set_color(png017::ColorType::Rgb);
    enc.set_depth(png017::BitDepth::Eight);
    enc.set_compression(png017::Compression::Fast);
    enc.set_filter(png017::FilterType::Sub);
    enc.set_adaptive_filter(png017::AdaptiveFilterType::Adaptive);
    let mut writer = enc.write_header()?;
    writer.write_image_data(rgb)?;
    writer.finish()?;
    Ok(bytes)
}

fn position(c: Corner) -> SeriesLabelPosition {
    match c {
        Corner::LowerLeft => SeriesLabelPosition::LowerLeft,
        Corner::LowerRight => SeriesLabelPosition::LowerRight,
        Corner::UpperLeft => SeriesLabelPosition::UpperLeft,
        Corner::UpperRight => SeriesLabelPosition::UpperRight,
    }
}

/// The chart's frame, ticks, curves (lines with a dot at every point) and legend on `root`,
/// over the axes `x` and `y`.
fn draw<'a, X, Y>(
    c: &'a Chart,
    root: &'a Area,
    x: X,
    y: Y,
    corner: SeriesLabelPosition,
) -> Result<(), Box<dyn std::error::Error + 'a>>
where
    X: plotters::coord::ranged1d::AsRangedCoord<Value = f64>,
    Y: plotters::coord::ranged1d::AsRangedCoord<Value = f64>,
    X::CoordDescType: plotters::coord::ranged1d::ValueFormatter<f64>,
    Y::CoordDescType: plotters::coord::ranged1d::ValueFormatter<f64>,
{
    let mut chart = ChartBuilder::on(root)
        .caption(&c.title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x, y)?;
    chart
        .configure_mesh()
        .x_desc(&c.x_label)
        .y_desc(&c.y_label)
        .label_style(("sans-serif", 13))
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .draw()?;
    for (i, s) in c.series.iter().enumerate() {
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

#[cfg(test)]
mod tests {
    use super::*;
    use csgpix_run::plot::Series;

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
        for log in [false, true] {
            let bytes = Plotters
                .png(
                    &chart(log, vec![(1.0, 2.0), (10.0, 40.0), (100.0, 3.0)]),
                    320,
                    240,
                )
                .unwrap();
            let img = image::load_from_memory(&bytes).unwrap().to_rgb8();
            assert_eq!(img.dimensions(), (320, 240));
            // Not blank: text and curve leave dark pixels.
            let dark = img
                .pixels()
                .filter(|p| p.0.iter().all(|&c| c < 100))
                .count();
            assert!(dark > 200, "{dark} dark pixels");
        }
    }

    /// The bytes are those plotters' bitmap backend writes to a file.
    #[test]
    fn the_bytes_are_those_plotters_writes() {
        let dir = tempfile::tempdir().unwrap();
        let c = chart(true, vec![(1.0, 2.0), (10.0, 40.0), (100.0, 3.0)]);
        let path = dir.path().join("c.png");
        register_font();
        let ranges = c.ranges().unwrap();
        let corner = position(c.legend_corner(ranges));
        let ((x0, x1), (y0, y1)) = ranges;
        {
            let root = BitMapBackend::new(&path, (320, 240)).into_drawing_area();
            root.fill(&WHITE).unwrap();
            let (x, y) = ((x0..x1).log_scale(), (y0..y1).log_scale());
            draw(&c, &root, x, y, corner).unwrap();
            root.present().unwrap();
        }
        let bytes = Plotters.png(&c, 320, 240).unwrap();
        assert!(bytes == std::fs::read(&path).unwrap());
    }

    #[test]
    fn refuses_bad_values() {
        assert!(Plotters
            .png(&chart(true, vec![(0.0, 1.0)]), 100, 100)
            .is_err());
        let nan = chart(false, vec![(f64::NAN, 1.0)]);
        assert!(Plotters.png(&nan, 100, 100).is_err());
    }
}
