//! Draws lambda* against the Johnson parameter from the CSV of the
//! `transition` example (`docs/solver-lambda-star.csv`) as a plain SVG: one
//! colour per beta, lambda* at f = 5 % with its uncertainty as a bar, the 1 %
//! and 10 % thresholds as small open markers; rows without a lambda* or with
//! an uncertainty above 50 % are left out (named in the caption).
//!
//! `cargo run --release -p maugis-solver --example lambda_star_plot -- docs/solver-lambda-star.csv docs/solver-lambda-star.svg`

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let text = std::fs::read_to_string(&a[0]).expect("read the CSV");
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().expect("a header").split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("no column {name}"));
    let (c_chi, c_beta, c_f, c_star, c_unc) = (col("chi"), col("beta"), col("fraction"), col("lambda_star"), col("rel_uncertainty"));
    // (beta, chi, fraction, lambda*, uncertainty)
    let mut rows: Vec<(f64, f64, f64, f64, f64)> = Vec::new();
    let mut left_out = Vec::new();
    for l in lines {
        let f: Vec<&str> = l.split(',').collect();
        let num = |i: usize| f.get(i).and_then(|s| s.parse::<f64>().ok());
        match (num(c_beta), num(c_chi), num(c_f), num(c_star), num(c_unc)) {
            (Some(b), Some(c), Some(fr), Some(s), Some(u)) if u <= 0.5 => rows.push((b, c, fr, s, u)),
            (Some(b), Some(c), Some(fr), ..) if fr == 0.05 => left_out.push(format!("beta = {b}, chi = {c}")),
            _ => {}
        }
    }
    // a roughness whose f = 5 % search is not resolved is left out at every threshold
    rows.retain(|r| !left_out.contains(&format!("beta = {}, chi = {}", r.0, r.1)));
    let (w, h, left, right, top, bottom) = (780.0, 540.0, 80.0, 240.0, 60.0, 60.0);
    let (x0, x1) = (1.5, 5.5);
    let (ly0, ly1) = (0.3f64.log10(), 3.0f64.log10());
    let px = |chi: f64| left + (chi - x0) / (x1 - x0) * (w - left - right);
    let py = |lam: f64| top + (ly1 - lam.log10()) / (ly1 - ly0) * (h - top - bottom);
    let mut s = format!(r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="14">
<rect width="{w}" height="{h}" fill="white"/>
<text x="{}" y="28" text-anchor="middle" font-size="16">lambda* against the Johnson parameter (solver, W below f W_JKR)</text>
<rect x="{left}" y="{top}" width="{}" height="{}" fill="none" stroke="black"/>
"#, (w - right + left) / 2.0, w - left - right, h - top - bottom);
    for chi in [2.0, 3.0, 4.0, 5.0] {
        s += &format!("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{chi}</text>\n", px(chi), h - bottom + 20.0);
    }
    for lam in [0.3, 0.5, 1.0, 2.0, 3.0] {
        let y = py(lam);
        s += &format!("<line x1=\"{left}\" x2=\"{}\" y1=\"{y}\" y2=\"{y}\" stroke=\"#ddd\"/><text x=\"{}\" y=\"{}\" text-anchor=\"end\">{lam}</text>\n", w - right, left - 8.0, y + 5.0);
    }
    s += &format!("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">Johnson parameter chi = sqrt(beta/alpha^2)</text>\n", (w - right + left) / 2.0, h - 15.0);
    s += &format!("<text transform=\"translate(22 {}) rotate(-90)\" text-anchor=\"middle\">lambda* (log scale)</text>\n", (h - bottom + top) / 2.0);
    // the legend's frame (white box, grey outline)
    s += &format!("<rect x=\"{}\" y=\"{}\" width=\"225\" height=\"92\" fill=\"white\"/><rect x=\"{}\" y=\"{}\" width=\"225\" height=\"92\" fill=\"none\" stroke=\"#8c8c8c\"/>\n", w - right + 6.0, top + 4.0, w - right + 6.0, top + 4.0);
    let colours = [(1.125, "#1f5bb4", "beta = 9/8"), (2.0, "#d66018", "beta = 2")];
    for (k, &(beta, colour, label)) in colours.iter().enumerate() {
        let mut main: Vec<(f64, f64, f64)> = rows.iter().filter(|r| r.0 == beta && r.2 == 0.05).map(|r| (r.1, r.3, r.4)).collect();
        main.sort_by(|a, b| a.0.total_cmp(&b.0));
        let path: Vec<String> = main.iter().map(|&(c, l, _)| format!("{:.1},{:.1}", px(c), py(l))).collect();
        s += &format!("<polyline fill=\"none\" stroke=\"{colour}\" stroke-width=\"2\" points=\"{}\"/>\n", path.join(" "));
        for &(c, l, u) in &main {
            let (ylo, yhi) = (py(l * (-u).exp()), py(l * u.exp()));
            s += &format!("<line x1=\"{x}\" x2=\"{x}\" y1=\"{ylo:.1}\" y2=\"{yhi:.1}\" stroke=\"{colour}\" stroke-width=\"2\"/><circle cx=\"{x}\" cy=\"{:.1}\" r=\"5\" fill=\"{colour}\" stroke=\"none\"/>\n", py(l), x = px(c));
        }
        for r in rows.iter().filter(|r| r.0 == beta && r.2 != 0.05) {
            s += &format!("<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3.5\" fill=\"white\" stroke=\"{colour}\"/>\n", px(r.1), py(r.3));
        }
        let ly = top + 20.0 + 26.0 * k as f64;
        s += &format!("<line x1=\"{}\" x2=\"{}\" y1=\"{ly}\" y2=\"{ly}\" stroke=\"{colour}\" stroke-width=\"2\"/><circle cx=\"{}\" cy=\"{ly}\" r=\"5\" fill=\"{colour}\" stroke=\"none\"/><text x=\"{}\" y=\"{}\">{label}, f = 5 %</text>\n", w - right + 12.0, w - right + 42.0, w - right + 27.0, w - right + 50.0, ly + 5.0);
    }
    let ly = top + 20.0 + 52.0;
    s += &format!("<circle cx=\"{}\" cy=\"{ly}\" r=\"3.5\" fill=\"white\" stroke=\"black\"/><text x=\"{}\" y=\"{}\">f = 1 % (below), 10 %</text>\n", w - right + 27.0, w - right + 50.0, ly + 5.0);
    if !left_out.is_empty() {
        s += &format!("<text x=\"{left}\" y=\"48\" font-size=\"12\">not resolved, left out: {}</text>\n", left_out.join("; "));
    }
    s += "</svg>\n";
    std::fs::write(&a[1], s).expect("write the SVG");
}
