//! Small drawing helpers shared by the SVG plots (`plotters`, SVG backend).
//!
//! * [`PALETTE`]: distinct curve colours (the Tableau 10 set without grey).
//! * [`clip_y`]: cuts a polyline to a vertical window, interpolating the
//!   crossing points, so lines that leave the plot stop at its border.
//! * Marker shapes in pixel offsets: [`triangle_up`], [`triangle_down`],
//!   [`arrow_head`].
//! * [`Legend`]: the legend box, drawn beside or inside a chart, sized to its labels.
//! * [`plot_err`]: turns a `plotters` error into the one-line message the CLI prints.

use plotters::coord::{CoordTranslate, Shift};
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

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

/// Width of the legend column to the right of the load-area plots (pixels): it
/// holds the longest label of `maugis curve` at [`LEGEND_FONT`] by the
/// [`Legend`] width estimate.
pub const LEGEND_WIDTH: u32 = 600;

/// Font size of the legends beside the load-area plots (plotters units: the SVG
/// `font-size` is this over 1.24).
pub const LEGEND_FONT: f64 = 16.0;

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
    root: &'a DrawingArea<SVGBackend<'b>, Shift>,
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
    root: &'a DrawingArea<SVGBackend<'b>, Shift>,
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

/// Draws `legend` to the right of the chart's plotting area (outside the data,
/// in the [`LEGEND_WIDTH`] column kept free by [`xy_chart`]) and finishes the SVG.
pub fn finish_load_area_chart<DB: DrawingBackend, CT: CoordTranslate>(
    chart: &ChartContext<'_, DB, CT>,
    root: &DrawingArea<DB, Shift>,
    legend: &Legend,
) -> Result<(), String> {
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let (root_w, _) = root.dim_in_pixel();
    let x = xs.end + 20;
    legend.draw(root, (x, ys.start), root_w as i32 - x - 10)?;
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

// ---------------------------------------------------------------- legend

/// One shape of a legend swatch, in pixels relative to the swatch's centre
/// (the swatch is [`Legend::SWATCH`] wide, `x` in `-SWATCH/2..=SWATCH/2`).
#[derive(Clone, Debug)]
pub enum Mark {
    /// A polyline, solid when `dash == 0`, else `dash` on, `gap` off.
    Line { points: Vec<(i32, i32)>, style: ShapeStyle, dash: u32, gap: u32 },
    /// A filled polygon, outlined when `outline` is set.
    Polygon { points: Vec<(i32, i32)>, fill: ShapeStyle, outline: Option<ShapeStyle> },
    /// A filled circle of radius `r` about `centre`, outlined when `outline` is set.
    Circle { centre: (i32, i32), r: u32, fill: ShapeStyle, outline: Option<ShapeStyle> },
    /// A rectangle between two corners (filled or not, as `style` says).
    Rect { from: (i32, i32), to: (i32, i32), style: ShapeStyle },
}

impl Mark {
    /// A marker polygon (e.g. [`triangle_up`]) about the swatch's centre.
    pub fn polygon(points: Vec<(i32, i32)>, fill: ShapeStyle, outline: Option<ShapeStyle>) -> Mark {
        Mark::Polygon { points, fill, outline }
    }

    /// A circle about the swatch's centre.
    pub fn circle(r: u32, fill: ShapeStyle, outline: Option<ShapeStyle>) -> Mark {
        Mark::Circle { centre: (0, 0), r, fill, outline }
    }

    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>, (cx, cy): (i32, i32)) -> Result<(), String> {
        let at = |pts: &[(i32, i32)]| pts.iter().map(|&(x, y)| (cx + x, cy + y)).collect::<Vec<_>>();
        let drawn = || match self {
            Mark::Line { points, style, dash: 0, .. } => area.draw(&PathElement::new(at(points), *style)),
            Mark::Line { points, style, dash, gap } => area.draw(&DashedPathElement::new(at(points), *dash, *gap, *style)),
            Mark::Polygon { points, fill, outline } => {
                area.draw(&Polygon::new(at(points), *fill))?;
                match outline {
                    Some(o) => {
                        let mut ring = at(points);
                        ring.extend(ring.first().copied());
                        area.draw(&PathElement::new(ring, *o))
                    }
                    None => Ok(()),
                }
            }
            Mark::Circle { centre, r, fill, outline } => {
                let c = (cx + centre.0, cy + centre.1);
                area.draw(&Circle::new(c, *r, *fill))?;
                match outline {
                    Some(o) => area.draw(&Circle::new(c, *r, *o)),
                    None => Ok(()),
                }
            }
            Mark::Rect { from, to, style } => area.draw(&Rectangle::new([(cx + from.0, cy + from.1), (cx + to.0, cy + to.1)], *style)),
        };
        drawn().map_err(plot_err)
    }
}

/// A legend drawn by us, not by `plotters`' `configure_series_labels`: that one
/// is confined to the plotting area (it clamps every coordinate into it, so a
/// legend placed beside the data collapsed to a box of width 0, with its
/// swatches at one point over the first letter of each label), and it sizes
/// its box from a text-width estimate that counts UTF-8 bytes.
///
/// Layout, in pixels, from the box's top-left corner: a padding of
/// [`Legend::PAD`], then per entry a row of height `row` (1.8 em): the swatch,
/// [`Legend::SWATCH`] wide, the gap [`Legend::GAP`], and the label, left-aligned
/// and vertically centred on the row. Nothing is drawn over a label.
///
/// An SVG does not know the width of its text (the viewer picks the font), so the
/// box is sized from an estimate of [`Legend::CHAR_EM`] em per character (not
/// counting combining marks). With DejaVu Sans, one of the widest sans-serif
/// fonts, the labels drawn here measure 0.45 to 0.55 em per character (digits
/// 0.64), so the estimate is generous; `tests/render` checks with DejaVu Sans that
/// every label lies inside its box. The box is opaque white with a grey
/// frame (`tests/render` finds legends as framed boxes that hold text).
#[derive(Clone, Debug)]
pub struct Legend {
    size: f64,
    entries: Vec<(String, Vec<Mark>)>,
}

impl Legend {
    /// Padding inside the box.
    pub const PAD: i32 = 10;
    /// Width of a swatch.
    pub const SWATCH: i32 = 40;
    /// Gap between a swatch and its label.
    pub const GAP: i32 = 10;
    /// Estimated width of one character, in em.
    pub const CHAR_EM: f64 = 0.6;

    /// An empty legend with labels at font size `size` (plotters units).
    pub fn new(size: f64) -> Legend {
        Legend { size, entries: Vec::new() }
    }

    /// An entry drawn by `marks`.
    pub fn entry(&mut self, label: impl Into<String>, marks: Vec<Mark>) -> &mut Self {
        self.entries.push((label.into(), marks));
        self
    }

    /// An entry for a line in `style`, solid when `dash == 0`; long dashes are
    /// shortened so that the swatch shows at least two of them.
    pub fn line(&mut self, label: impl Into<String>, style: ShapeStyle, dash: u32, gap: u32) -> &mut Self {
        let h = Self::SWATCH / 2;
        let (dash, gap) = if dash == 0 { (0, 0) } else { (dash.min(14), gap.min(6)) };
        self.entry(label, vec![Mark::Line { points: vec![(-h, 0), (h, 0)], style, dash, gap }])
    }

    /// The SVG font size (em, pixels) of the labels at plotters size `size`.
    fn em(size: f64) -> f64 {
        size / 1.24
    }

    /// Estimated width of `text` at plotters size `size`.
    pub fn text_width(text: &str, size: f64) -> i32 {
        let chars = text.chars().filter(|c| !('\u{300}'..='\u{36f}').contains(c)).count();
        (chars as f64 * Self::CHAR_EM * Self::em(size)).ceil() as i32
    }

    fn row(size: f64) -> i32 {
        (1.8 * Self::em(size)).round().max(16.0) as i32
    }

    /// Width and height of the box at label size `size`.
    fn dims(&self, size: f64) -> (i32, i32) {
        let text = self.entries.iter().map(|(l, _)| Self::text_width(l, size)).max().unwrap_or(0);
        (2 * Self::PAD + Self::SWATCH + Self::GAP + text, 2 * Self::PAD + Self::row(size) * self.entries.len() as i32)
    }

    /// Width and height of the box, in pixels.
    pub fn size(&self) -> (i32, i32) {
        self.dims(self.size)
    }

    /// Draws the legend with its box's top-left corner at `(x, y)` of `area`; if
    /// it would be wider than `max_width`, the labels are set smaller to fit.
    pub fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>, (x, y): (i32, i32), max_width: i32) -> Result<(), String> {
        if self.entries.is_empty() {
            return Ok(());
        }
        let mut size = self.size;
        let (w, _) = self.dims(size);
        if w > max_width {
            let fixed = 2 * Self::PAD + Self::SWATCH + Self::GAP;
            size *= f64::from((max_width - fixed).max(1)) / f64::from(w - fixed);
        }
        let (w, h) = self.dims(size);
        let row = Self::row(size);
        area.draw(&Rectangle::new([(x, y), (x + w, y + h)], WHITE.filled())).map_err(plot_err)?;
        area.draw(&Rectangle::new([(x, y), (x + w, y + h)], BLACK.mix(0.55).stroke_width(1))).map_err(plot_err)?;
        let style = TextStyle::from(("sans-serif", size).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
        for (i, (label, marks)) in self.entries.iter().enumerate() {
            let cy = y + Self::PAD + row * i as i32 + row / 2;
            let centre = (x + Self::PAD + Self::SWATCH / 2, cy);
            for m in marks {
                m.draw(area, centre)?;
            }
            area.draw(&Text::new(label.as_str(), (x + Self::PAD + Self::SWATCH + Self::GAP, cy), style.clone())).map_err(plot_err)?;
        }
        Ok(())
    }
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
