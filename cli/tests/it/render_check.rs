//! The picture checks of `render` themselves: a legend drawn the way the broken
//! plotters legend was (marker over the label, a coloured line without an
//! entry, a label wider than its box) fails them, a sound one passes.

use crate::render;

use std::path::PathBuf;

/// A 400 x 120 picture: a blue data line, a legend box at x = 200..`box_right`
/// with one entry whose marker sits at `marker_x` and whose swatch is `swatch`.
fn picture(box_right: u32, marker_x: u32, swatch: &str) -> String {
    format!(
        r##"<svg width="400" height="120" viewBox="0 0 400 120" xmlns="http://www.w3.org/2000/svg">
<rect x="0" y="0" width="400" height="120" opacity="1" fill="#FFFFFF" stroke="none"/>
<polyline fill="none" opacity="1" stroke="#1F77B4" stroke-width="3" points="10,100 150,20 "/>
<rect x="200" y="20" width="{w}" height="40" opacity="1" fill="#FFFFFF" stroke="none"/>
<rect x="200" y="20" width="{w}" height="40" opacity="0.55" fill="none" stroke="#000000"/>
<polyline fill="none" opacity="1" stroke="{swatch}" stroke-width="3" points="210,40 240,40 "/>
<circle cx="{marker_x}" cy="40" r="5" opacity="1" fill="#787878" stroke="none"/>
<text x="255" y="40" dy="0.5ex" text-anchor="start" font-family="sans-serif" font-size="12" opacity="1" fill="#000000">
λ = 3
</text>
</svg>
"##,
        w = box_right - 200
    )
}

fn check(name: &str, svg: &str) -> Result<render::Report, String> {
    let path: PathBuf = std::env::temp_dir().join(format!("maugis-render-check-{}-{name}.svg", std::process::id()));
    std::fs::write(&path, svg).unwrap();
    let r = std::panic::catch_unwind(|| render::check_svg(&path)).map_err(|e| e.downcast_ref::<String>().cloned().unwrap_or_default());
    let _ = std::fs::remove_file(&path);
    let _ = std::fs::remove_file(path.with_extension("png"));
    r
}

#[test]
fn a_sound_legend_passes() {
    let report = check("sound", &picture(320, 225, "#1F77B4")).expect("a sound legend");
    let e = report.entry("λ = 3");
    assert!(e.colours.iter().any(|c| c.rgb == [0x1F, 0x77, 0xB4] && c.chromatic()), "{e:?}");
}

#[test]
fn broken_legends_fail() {
    // the marker over the label's first letter
    let msg = check("over", &picture(320, 258, "#1F77B4")).unwrap_err();
    assert!(msg.contains("\"λ = 3\" is overprinted"), "{msg}");
    // a black swatch: the blue line is explained by no entry
    let msg = check("black", &picture(320, 225, "#000000")).unwrap_err();
    assert!(msg.contains("a line in colour [31, 119, 180] has no legend entry"), "{msg}");
    // a box narrower than its label
    let msg = check("narrow", &picture(280, 225, "#1F77B4")).unwrap_err();
    assert!(msg.contains("overflows its legend box"), "{msg}");
}
