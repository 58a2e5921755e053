//! Curves against the view's turn, for `cube angles` (Fig. 14) and `cube
//! gradients` (Fig. 15): lines in given colours and widths, and the
//! paper's levels dashed, as an RGB buffer for `output::Files::png_rgb8`.

use anyhow::Result;
use plotters::prelude::*;

pub const PLOT_W: u32 = 800;
pub const PLOT_H: u32 = 500;

/// One curve: its legend, colour, stroke width and points.
pub struct Curve {
    pub label: String,
    pub colour: RGBColor,
    pub width: u32,
    pub points: Vec<(f64, f64)>,
}

/// A figure of `curves` against angle from `from` to `to` degrees, with a
/// dashed line at each of `levels` (the paper's figures, labelled).
pub fn angle_plot(
    title: &str,
    y_desc: &str,
    curves: &[Curve],
    levels: &[(String, f64)],
    from: f64,
    to: f64,
) -> Result<Vec<u8>> {
    // Text needs a font that every machine has: DejaVu Sans, embedded.
    plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| anyhow::anyhow!("registering the embedded font"))?;
    let mut buf = vec![0u8; (PLOT_W * PLOT_H * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (PLOT_W, PLOT_H)).into_drawing_area();
        root.fill(&WHITE)?;
        let top = curves
            .iter()
            .flat_map(|c| c.points.iter().map(|p| p.1))
            .chain(levels.iter().map(|l| l.1))
            .fold(1.0, f64::max)
            * 1.1;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(40)
            .y_label_area_size(55)
            .build_cartesian_2d(from..to.max(from + 1.0), 0.0..top)?;
        chart
            .configure_mesh()
            .x_desc("rotation about the vertical axis (degrees)")
            .y_desc(y_desc)
            .draw()?;
        for c in curves {
            let style = c.colour.stroke_width(c.width);
            chart
                .draw_series(LineSeries::new(c.points.iter().copied(), style))?
                .label(c.label.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
        }
        let paper = BLACK.mix(0.6).stroke_width(1);
        for (label, y) in levels {
            chart
                .draw_series(DashedLineSeries::new([(from, *y), (to, *y)], 6, 4, paper))?
                .label(label.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], paper));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
        root.present()?;
    }
    Ok(buf)
}
