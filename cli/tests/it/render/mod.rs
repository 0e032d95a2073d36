//! Renders the SVGs the CLI writes with a real renderer (`resvg`) and checks
//! the pictures' legends, so that a legend nobody can read fails a test.
//!
//! Text is laid out with DejaVu Sans, embedded by the `dejavu` crate, so the
//! checks need no system font; DejaVu Sans is one of the widest sans-serif
//! fonts, so a label that fits with it fits with the fonts viewers usually pick.
//!
//! [`check_svg`] finds each legend as a framed box (a filled shape and a stroked
//! one on the same rectangle) that holds text, and for every label in it checks:
//!
//! * the label lies inside its box, and every text inside the picture;
//! * the swatch, the part of the label's row left of the label, has shapes, and
//!   each colour they are declared with shows in the rendered pixels there;
//! * no shape is drawn over the label: rendered without its text, the picture
//!   is plain background inside every label's text box.
//!
//! And for the whole picture: every coloured (non-grey) line of the data has
//! its colour in some legend swatch, so no colour goes unexplained.
//!
//! The PNG is written next to the SVG (`<name>.png`), and also into the folder
//! `MAUGIS_RENDER_DIR` names, when it is set, to look at.

use std::path::Path;
use std::sync::Arc;

use resvg::tiny_skia::{Pixmap, Transform};
use resvg::usvg::{self, Node, Paint};

/// An axis-aligned box, in pixels.
#[derive(Clone, Copy, Debug)]
pub struct Rect {
    pub left: f32,
    pub top: f32,
    pub right: f32,
    pub bottom: f32,
}

impl Rect {
    fn of(r: usvg::Rect) -> Rect {
        Rect { left: r.left(), top: r.top(), right: r.right(), bottom: r.bottom() }
    }

    fn centre(&self) -> (f32, f32) {
        ((self.left + self.right) / 2.0, (self.top + self.bottom) / 2.0)
    }

    fn holds(&self, (x, y): (f32, f32)) -> bool {
        x >= self.left && x <= self.right && y >= self.top && y <= self.bottom
    }

    fn near(&self, o: &Rect, tol: f32) -> bool {
        (self.left - o.left).abs() <= tol && (self.top - o.top).abs() <= tol && (self.right - o.right).abs() <= tol && (self.bottom - o.bottom).abs() <= tol
    }

    /// Whether `inner` lies inside, allowing `tol` pixels of overhang.
    fn contains(&self, inner: &Rect, tol: f32) -> bool {
        inner.left >= self.left - tol && inner.right <= self.right + tol && inner.top >= self.top - tol && inner.bottom <= self.bottom + tol
    }
}

/// A colour as declared in the SVG, with its effective opacity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Paint3 {
    pub rgb: [u8; 3],
    pub alpha: f32,
}

impl Paint3 {
    /// Not a grey: the channels differ by more than 40.
    pub fn chromatic(&self) -> bool {
        let (lo, hi) = (self.rgb.iter().min().unwrap(), self.rgb.iter().max().unwrap());
        hi - lo > 40
    }
}

/// A drawn shape: its box and its fill and stroke colours.
#[derive(Clone, Debug)]
struct Shape {
    bbox: Rect,
    fill: Option<Paint3>,
    stroke: Option<Paint3>,
}

/// A text element: its string and its laid-out box.
#[derive(Clone, Debug)]
struct Label {
    text: String,
    bbox: Rect,
}

/// One legend entry as found in the picture.
#[derive(Clone, Debug)]
pub struct Entry {
    pub label: String,
    /// The colours the swatch's shapes are declared with.
    pub colours: Vec<Paint3>,
}

/// What [`check_svg`] found: the legends, each a list of entries top to bottom.
#[derive(Debug)]
pub struct Report {
    pub legends: Vec<Vec<Entry>>,
}

impl Report {
    /// All entries of all legends.
    pub fn entries(&self) -> impl Iterator<Item = &Entry> {
        self.legends.iter().flatten()
    }

    /// The entry whose label is `label`; panics when there is none.
    #[allow(dead_code)] // a shared test module: the figures test binary does not call it
    pub fn entry(&self, label: &str) -> &Entry {
        self.entries()
            .find(|e| e.label == label)
            .unwrap_or_else(|| panic!("no legend entry {label:?}; entries: {:?}", self.entries().map(|e| &e.label).collect::<Vec<_>>()))
    }
}

fn options() -> usvg::Options<'static> {
    let mut db = usvg::fontdb::Database::new();
    db.load_font_data(dejavu::sans::regular().to_vec());
    db.set_sans_serif_family("DejaVu Sans");
    usvg::Options { font_family: "DejaVu Sans".into(), fontdb: Arc::new(db), ..usvg::Options::default() }
}

fn render(tree: &usvg::Tree) -> Pixmap {
    let size = tree.size().to_int_size();
    let mut pixmap = Pixmap::new(size.width(), size.height()).expect("a picture of non-zero size");
    resvg::render(tree, Transform::identity(), &mut pixmap.as_mut());
    pixmap
}

fn paint(p: &Paint, opacity: f32) -> Option<Paint3> {
    match p {
        Paint::Color(c) => Some(Paint3 { rgb: [c.red, c.green, c.blue], alpha: opacity }),
        _ => None,
    }
}

/// Collects the shapes and texts of `g`, with the opacity of their groups.
fn walk(g: &usvg::Group, opacity: f32, shapes: &mut Vec<Shape>, labels: &mut Vec<Label>) {
    for node in g.children() {
        match node {
            Node::Group(c) => walk(c, opacity * c.opacity().get(), shapes, labels),
            Node::Path(p) => shapes.push(Shape {
                bbox: Rect::of(p.abs_bounding_box()),
                fill: p.fill().and_then(|f| paint(f.paint(), opacity * f.opacity().get())),
                stroke: p.stroke().and_then(|s| paint(s.paint(), opacity * s.opacity().get())),
            }),
            Node::Text(t) => labels.push(Label { text: t.chunks().iter().map(|c| c.text()).collect(), bbox: Rect::of(t.abs_bounding_box()) }),
            Node::Image(_) => {}
        }
    }
}

/// The SVG without its `<text>` elements.
fn without_text(svg: &str) -> String {
    let mut out = String::with_capacity(svg.len());
    let mut rest = svg;
    while let Some(i) = rest.find("<text") {
        out.push_str(&rest[..i]);
        let end = rest[i..].find("</text>").expect("a closed <text> element");
        rest = &rest[i + end + "</text>".len()..];
    }
    out.push_str(rest);
    out
}

fn pixel(p: &Pixmap, x: i32, y: i32) -> [f32; 3] {
    let c = p.pixel(x as u32, y as u32).expect("a pixel inside the picture").demultiply();
    [f32::from(c.red()), f32::from(c.green()), f32::from(c.blue())]
}

/// Pixel indices of the pixels whose centres lie inside `r`.
fn pixels_in(r: &Rect, p: &Pixmap) -> impl Iterator<Item = (i32, i32)> {
    let x0 = (r.left - 0.5).ceil().max(0.0) as i32;
    let x1 = ((r.right - 0.5).floor() as i32).min(p.width() as i32 - 1);
    let y0 = (r.top - 0.5).ceil().max(0.0) as i32;
    let y1 = ((r.bottom - 0.5).floor() as i32).min(p.height() as i32 - 1);
    (y0..=y1).flat_map(move |y| (x0..=x1).map(move |x| (x, y)))
}

/// The colour `c`, composited over `bg` with its opacity, minus `bg`.
fn offset(c: Paint3, bg: [f32; 3]) -> [f32; 3] {
    [0, 1, 2].map(|k| c.alpha * (f32::from(c.rgb[k]) - bg[k]))
}

/// Whether `c` stands out from `bg` (composited, more than 30 of 255 away).
fn stands_out(c: Paint3, bg: [f32; 3]) -> bool {
    offset(c, bg).iter().map(|v| v * v).sum::<f32>().sqrt() >= 30.0
}

/// Whether some pixel in `r` shows `c` over the background `bg`: a pixel on the
/// segment from `bg` to the composited colour, at least half way, as an
/// antialiased edge or a fully covered pixel is. Colours too close to the
/// background to be seen (a hollow marker's white fill) count as shown.
fn shows(p: &Pixmap, r: &Rect, c: Paint3, bg: [f32; 3]) -> bool {
    let d = offset(c, bg);
    let dd: f32 = d.iter().map(|v| v * v).sum();
    if !stands_out(c, bg) {
        return true;
    }
    pixels_in(r, p).any(|(x, y)| {
        let q = pixel(p, x, y);
        let t = (0..3).map(|k| (q[k] - bg[k]) * d[k]).sum::<f32>() / dd;
        let res: f32 = (0..3).map(|k| (q[k] - bg[k] - t * d[k]).powi(2)).sum::<f32>().sqrt();
        t >= 0.5 && res <= 20.0
    })
}

/// Renders the SVG at `path` to PNG and checks its legends (module docs);
/// panics with every problem found, and returns the legends.
pub fn check_svg(path: &Path) -> Report {
    let svg = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let opt = options();
    let tree = usvg::Tree::from_str(&svg, &opt).unwrap_or_else(|e| panic!("{}: not an SVG resvg reads: {e}", path.display()));
    let bare = usvg::Tree::from_str(&without_text(&svg), &opt).expect("the SVG without text parses");
    let picture = render(&tree);
    let plain = render(&bare);
    picture.save_png(path.with_extension("png")).expect("the PNG is written");
    if let Some(dir) = std::env::var_os("MAUGIS_RENDER_DIR") {
        let name = format!("{}-{}.png", path.parent().and_then(|p| p.file_name()).and_then(|n| n.to_str()).unwrap_or("svg"), path.file_stem().unwrap().to_string_lossy());
        picture.save_png(Path::new(&dir).join(name)).expect("the PNG is copied");
    }

    let (mut shapes, mut labels) = (Vec::new(), Vec::new());
    walk(tree.root(), 1.0, &mut shapes, &mut labels);
    let name = path.display();
    let mut problems: Vec<String> = Vec::new();
    let canvas = Rect { left: 0.0, top: 0.0, right: picture.width() as f32, bottom: picture.height() as f32 };
    for l in &labels {
        if !canvas.contains(&l.bbox, 0.5) {
            problems.push(format!("text {:?} leaves the picture: {:?}", l.text, l.bbox));
        }
        // nothing but the text inside its box: rendered without text, the box
        // is one colour
        let px: Vec<[f32; 3]> = pixels_in(&l.bbox, &plain).map(|(x, y)| pixel(&plain, x, y)).collect();
        let Some(&first) = px.first() else { continue };
        let over = px.iter().filter(|p| p.iter().zip(first).any(|(a, b)| (a - b).abs() > 8.0)).count();
        if over > 0 {
            problems.push(format!("text {:?} is overprinted: {over} of {} pixels of its text box {:?} differ without the text", l.text, px.len(), l.bbox));
        }
    }

    // legends: framed boxes that hold text
    let boxes: Vec<Rect> = shapes
        .iter()
        .filter(|s| s.fill.is_some() && s.stroke.is_none())
        .filter(|s| shapes.iter().any(|t| t.fill.is_none() && t.stroke.is_some() && t.bbox.near(&s.bbox, 1.0)))
        .map(|s| s.bbox)
        .filter(|b| labels.iter().any(|l| b.holds(l.bbox.centre())))
        .collect();
    let in_a_box = |r: &Rect| boxes.iter().any(|b| b.holds(r.centre()));
    let mut legends = Vec::new();
    let mut swatch_rgb: Vec<[u8; 3]> = Vec::new();
    for b in &boxes {
        let bg = pixel(&plain, (b.left + 3.0) as i32, (b.top + 3.0) as i32);
        let mut rows: Vec<&Label> = labels.iter().filter(|l| b.holds(l.bbox.centre())).collect();
        rows.sort_by(|p, q| p.bbox.top.total_cmp(&q.bbox.top));
        let pitch = rows.windows(2).map(|w| w[1].bbox.centre().1 - w[0].bbox.centre().1).fold(f32::INFINITY, f32::min);
        let pitch = if pitch.is_finite() { pitch } else { rows[0].bbox.bottom - rows[0].bbox.top + 8.0 };
        let mut entries = Vec::new();
        for l in rows {
            if !b.contains(&l.bbox, 0.5) {
                problems.push(format!("label {:?} overflows its legend box: text {:?}, box {:?}", l.text, l.bbox, b));
            }
            let cy = l.bbox.centre().1;
            let swatch = Rect { left: b.left + 1.0, top: cy - pitch / 2.0 + 1.0, right: l.bbox.left - 1.0, bottom: cy + pitch / 2.0 - 1.0 };
            let colours: Vec<Paint3> = shapes
                .iter()
                .filter(|s| swatch.holds(s.bbox.centre()))
                .flat_map(|s| [s.fill, s.stroke])
                .flatten()
                .collect();
            if swatch.right - swatch.left < 10.0 {
                problems.push(format!("label {:?} has no room for a swatch left of it ({:?})", l.text, swatch));
            } else if colours.is_empty() {
                problems.push(format!("label {:?} has no swatch", l.text));
            } else {
                if !colours.iter().any(|c| stands_out(*c, bg)) {
                    problems.push(format!("the swatch of {:?} has no colour that stands out from the background: {colours:?}", l.text));
                }
                for c in &colours {
                    if !shows(&picture, &swatch, *c, bg) {
                        problems.push(format!("the swatch of {:?} does not show its colour {c:?} in {swatch:?}", l.text));
                    }
                }
            }
            swatch_rgb.extend(colours.iter().map(|c| c.rgb));
            entries.push(Entry { label: l.text.clone(), colours });
        }
        legends.push(entries);
    }

    // every coloured line of the data is explained by a swatch
    for s in shapes.iter().filter(|s| !in_a_box(&s.bbox)) {
        if let Some(c) = s.stroke.filter(Paint3::chromatic) {
            if !swatch_rgb.contains(&c.rgb) {
                problems.push(format!("a line in colour {:?} has no legend entry", c.rgb));
                swatch_rgb.push(c.rgb);
            }
        }
    }
    assert!(problems.is_empty(), "{name}:\n  {}", problems.join("\n  "));
    Report { legends }
}
