//! Small drawing helpers shared by the SVG plots (`plotters`, SVG backend).
//!
//! * [`PALETTE`]: distinct curve colours (the Tableau 10 set without grey).
//! * [`clip_y`]: cuts a polyline to a vertical window, interpolating the
//!   crossing points, so lines that leave the plot stop at its border.
//! * Marker shapes in pixel offsets: [`triangle_up`], [`triangle_down`],
//!   [`arrow_head`].
//! * [`plot_err`]: turns a `plotters` error into the one-line message the CLI prints.

use plotters::prelude::*;

/// Curve colours, in order.
pub const PALETTE: [RGBColor; 9] = [
    RGBColor(31, 119, 180),  // blue
    RGBColor(255, 127, 14),  // orange
    RGBColor(44, 160, 44),   // green
    RGBColor(214, 39, 40),   // red
    RGBColor(148, 103, 189), // purple
    RGBColor(140, 86, 75),   // brown
    RGBColor(227, 119, 194), // pink
    RGBColor(188, 189, 34),  // olive
    RGBColor(23, 190, 207),  // cyan
];

/// The `i`-th curve colour: the palette, then further hues spaced by the golden
/// angle at two lightness levels, so no colour repeats however many curves.
pub fn colour(i: usize) -> RGBColor {
    if let Some(&c) = PALETTE.get(i) {
        return c;
    }
    let k = (i - PALETTE.len()) as f64;
    let hue = (0.1 + k * 0.618_033_988_75).fract();
    let light = if (i - PALETTE.len()) % 2 == 0 { 0.42 } else { 0.58 };
    let HSLColor(h, s, l) = HSLColor(hue, 0.7, light);
    let c = HSLColor(h, s, l).to_rgba();
    RGBColor(c.0, c.1, c.2)
}

/// Width of the legend column to the right of the load-area plots (pixels).
pub const LEGEND_WIDTH: u32 = 470;

/// Dark grey of the JKR lines.
pub const DARK_GREY: RGBColor = RGBColor(70, 70, 70);
/// Light grey of the M-DMT lines.
pub const LIGHT_GREY: RGBColor = RGBColor(150, 150, 150);

/// An axis tick label: up to 3 decimals, trailing zeros trimmed, no `-0`.
pub fn tick(v: &f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" || s.is_empty() {
        "0".into()
    } else {
        s.to_string()
    }
}

/// A load-area chart (`abar` against `Lbar`) with the shared caption, label
/// areas and grid style of the `curve` and `limits` plots.
pub fn load_area_chart<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
    title: String,
    amax: f64,
    ymin: f64,
    ymax: f64,
) -> Result<ChartContext<'a, SVGBackend<'b>, Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>>, String> {
    xy_chart(root, title, (0.0, amax), (ymin, ymax), ("contact half-width abar", "load Lbar"))
}

/// A chart over `x` and `y` ranges with the shared style; the right
/// [`LEGEND_WIDTH`] pixels are kept free for the legend.
pub fn xy_chart<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
    title: String,
    x: (f64, f64),
    y: (f64, f64),
    desc: (&str, &str),
) -> Result<ChartContext<'a, SVGBackend<'b>, Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>>, String> {
    let mut chart = ChartBuilder::on(root)
        .caption(title, ("sans-serif", 24))
        .margin(20)
        .margin_right(LEGEND_WIDTH + 20)
        .x_label_area_size(60)
        .y_label_area_size(75)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .x_desc(desc.0)
        .y_desc(desc.1)
        .axis_desc_style(("sans-serif", 22))
        .label_style(("sans-serif", 17))
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(205, 205, 205))
        .draw()
        .map_err(plot_err)?;
    Ok(chart)
}

/// Draws the legend box to the right of the data (outside the plotting area)
/// and finishes the SVG.
pub fn finish_load_area_chart<'a, 'b: 'a>(
    mut chart: ChartContext<'a, SVGBackend<'b>, Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>>,
    root: &DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
) -> Result<(), String> {
    let (w, _) = chart.plotting_area().dim_in_pixel();
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::Coordinate(w as i32 + 16, 0))
        .margin(12)
        .legend_area_size(40)
        .label_font(("sans-serif", 17))
        .background_style(WHITE.mix(0.88))
        .border_style(BLACK.mix(0.6))
        .draw()
        .map_err(plot_err)?;
    root.present().map_err(plot_err)
}

/// Error text of a failed drawing call.
pub fn plot_err<E: std::fmt::Debug>(e: E) -> String {
    format!("could not draw the plot: {e:?}")
}

/// Splits the polyline `pts` into pieces inside `ymin <= y <= ymax`, adding the
/// points where it crosses the window's edges. Non-finite points break the line.
pub fn clip_y(pts: &[(f64, f64)], ymin: f64, ymax: f64) -> Vec<Vec<(f64, f64)>> {
    let inside = |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite() && p.1 >= ymin && p.1 <= ymax;
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    for (k, p) in pts.iter().enumerate() {
        let prev = if k > 0 { Some(pts[k - 1]) } else { None };
        let finite = p.0.is_finite() && p.1.is_finite();
        if let (Some(q), true) = (prev, finite) {
            if q.0.is_finite() && q.1.is_finite() {
                // the part of segment q -> p inside the window
                let (dy, dx) = (p.1 - q.1, p.0 - q.0);
                let t_at = |y: f64| if dy != 0.0 { (y - q.1) / dy } else { f64::NAN };
                let (mut t0, mut t1) = (0.0f64, 1.0f64);
                if dy != 0.0 {
                    let (ta, tb) = (t_at(ymin), t_at(ymax));
                    t0 = t0.max(ta.min(tb));
                    t1 = t1.min(ta.max(tb));
                } else if !(q.1 >= ymin && q.1 <= ymax) {
                    t0 = 1.0;
                    t1 = 0.0;
                }
                if t0 <= t1 {
                    let a = (q.0 + dx * t0, q.1 + dy * t0);
                    let b = (q.0 + dx * t1, q.1 + dy * t1);
                    if cur.is_empty() {
                        cur.push(a);
                    }
                    cur.push(b);
                    if t1 < 1.0 {
                        out.push(std::mem::take(&mut cur));
                    }
                } else if !cur.is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
                continue;
            }
        }
        if !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
        if inside(p) {
            cur.push(*p);
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out.retain(|piece| !piece.is_empty());
    out
}

/// Upward triangle (tip up) centred on the origin, `s` pixels half-size.
pub fn triangle_up(s: i32) -> Vec<(i32, i32)> {
    vec![(0, -s), (s, s * 3 / 4), (-s, s * 3 / 4)]
}

/// Downward triangle (tip down) centred on the origin.
pub fn triangle_down(s: i32) -> Vec<(i32, i32)> {
    vec![(0, s), (s, -s * 3 / 4), (-s, -s * 3 / 4)]
}

/// Arrow head with its tip at the origin, pointing right (`right`) or left.
pub fn arrow_head(right: bool, len: i32, half: i32) -> Vec<(i32, i32)> {
    let d = if right { -len } else { len };
    vec![(0, 0), (d, -half), (d, half)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clip_cuts_at_the_window() {
        let pts = [(0.0, 0.0), (1.0, 2.0), (2.0, 0.0), (3.0, 0.5)];
        let pieces = clip_y(&pts, -1.0, 1.0);
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[0], vec![(0.0, 0.0), (0.5, 1.0)]);
        assert_eq!(pieces[1], vec![(1.5, 1.0), (2.0, 0.0), (3.0, 0.5)]);
        assert!(clip_y(&[(0.0, 5.0), (1.0, 6.0)], -1.0, 1.0).is_empty());
        assert_eq!(tick(&-0.0000001), "0");
        assert_eq!(tick(&2.5), "2.5");
        assert_eq!(tick(&10.0), "10");
    }
}
