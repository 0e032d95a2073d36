//! Draws lambda* of both adhesion laws against the Johnson parameter, from the
//! CSVs of `lambda_star_coarse` (`docs/solver-lambda-star-dugdale.csv` and
//! `docs/solver-lambda-star-exp.csv`, same resolution: 2048 cells, 200 steps,
//! threshold 5 % of W_JKR), as a plain SVG: one colour per law, a filled disc for
//! beta = 9/8 and a filled square for beta = 2, the uncertainty as a bar
//! (bisection plus the measured grid shift, or plus the documented estimate of
//! 3.1 % where the grid check did not run), and the fine grid's lambda* (4096
//! cells, 400 steps) as an open marker where it was measured.
//!
//! `cargo run --release -p maugis-solver --example lambda_star_laws_plot -- docs/solver-lambda-star-dugdale.csv docs/solver-lambda-star-exp.csv docs/solver-lambda-star-laws.svg`

/// Grid part of the uncertainty where the grid check did not run (docs/solver-map.md).
const GRID_ESTIMATE: f64 = 0.031;

/// One row: (beta, chi, lambda*, relative uncertainty, fine lambda* if measured).
type Row = (f64, f64, f64, f64, Option<f64>);

fn read(path: &str) -> Vec<Row> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("read {path}: {e}"));
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().expect("a header").split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("{path}: no column {name}"));
    let (c_chi, c_beta, c_star, c_bis, c_fine, c_shift) =
        (col("chi"), col("beta"), col("lambda_star"), col("rel_bisection"), col("lambda_star_fine"), col("grid_shift"));
    lines
        .filter_map(|l| {
            // the first columns are plain numbers (the scan columns after them are quoted)
            let f: Vec<&str> = l.split(',').collect();
            let num = |i: usize| f.get(i).and_then(|s| s.parse::<f64>().ok());
            let (beta, chi, star, bis) = (num(c_beta)?, num(c_chi)?, num(c_star)?, num(c_bis)?);
            let unc = bis + num(c_shift).unwrap_or(GRID_ESTIMATE);
            Some((beta, chi, star, unc, num(c_fine)))
        })
        .collect()
}

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    if a.len() != 3 {
        eprintln!("usage: lambda_star_laws_plot DUGDALE.csv EXP.csv OUT.svg");
        std::process::exit(2);
    }
    let laws = [("Dugdale", "#1f5bb4", read(&a[0])), ("exponential (smooth)", "#d66018", read(&a[1]))];
    let (w, h, left, right, top, bottom) = (820.0, 560.0, 80.0, 280.0, 60.0, 60.0);
    let (x0, x1) = (2.2, 5.3);
    let (ly0, ly1) = (0.3f64.log10(), 2.6f64.log10());
    let px = |chi: f64| left + (chi - x0) / (x1 - x0) * (w - left - right);
    let py = |lam: f64| top + (ly1 - lam.clamp(0.3, 2.6).log10()) / (ly1 - ly0) * (h - top - bottom);
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="14">
<rect width="{w}" height="{h}" fill="white"/>
<text x="{}" y="28" text-anchor="middle" font-size="16">lambda* of both adhesion laws (solver, 2048 cells, 200 steps, 5 % of W_JKR)</text>
<rect x="{left}" y="{top}" width="{}" height="{}" fill="none" stroke="black"/>
"#,
        w / 2.0,
        w - left - right,
        h - top - bottom
    );
    for chi in [2.5, 3.0, 3.5, 4.0, 4.5, 5.0] {
        s += &format!("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{chi}</text>\n", px(chi), h - bottom + 20.0);
    }
    for lam in [0.3, 0.5, 0.7, 1.0, 1.5, 2.0] {
        let y = py(lam);
        s += &format!(
            "<line x1=\"{left}\" x2=\"{}\" y1=\"{y}\" y2=\"{y}\" stroke=\"#ddd\"/><text x=\"{}\" y=\"{}\" text-anchor=\"end\">{lam}</text>\n",
            w - right,
            left - 8.0,
            y + 5.0
        );
    }
    s += &format!(
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">Johnson parameter chi = sqrt(beta/alpha^2)</text>\n",
        (w - right + left) / 2.0,
        h - 15.0
    );
    s += &format!("<text transform=\"translate(22 {}) rotate(-90)\" text-anchor=\"middle\">lambda* (log scale)</text>\n", (h - bottom + top) / 2.0);
    let marker = |beta: f64, x: f64, y: f64, colour: &str, filled: bool| {
        let fill = if filled { colour } else { "white" };
        if beta == 2.0 {
            format!("<rect x=\"{:.1}\" y=\"{:.1}\" width=\"10\" height=\"10\" fill=\"{fill}\" stroke=\"{colour}\" stroke-width=\"2\"/>\n", x - 5.0, y - 5.0)
        } else {
            format!("<circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"5\" fill=\"{fill}\" stroke=\"{colour}\" stroke-width=\"2\"/>\n")
        }
    };
    for (k, (_, colour, rows)) in laws.iter().enumerate() {
        // the two laws side by side at each chi, so that their bars do not overlap
        let dx = if k == 0 { -5.0 } else { 5.0 };
        for beta in [1.125, 2.0] {
            let mut line: Vec<&Row> = rows.iter().filter(|r| r.0 == beta).collect();
            line.sort_by(|a, b| a.1.total_cmp(&b.1));
            let dash = if beta == 2.0 { " stroke-dasharray=\"6 4\"" } else { "" };
            let path: Vec<String> = line.iter().map(|r| format!("{:.1},{:.1}", px(r.1) + dx, py(r.2))).collect();
            s += &format!("<polyline fill=\"none\" stroke=\"{colour}\" stroke-width=\"2\"{dash} points=\"{}\"/>\n", path.join(" "));
            for &&(b, chi, star, unc, fine) in &line {
                let x = px(chi) + dx;
                s += &format!(
                    "<line x1=\"{x:.1}\" x2=\"{x:.1}\" y1=\"{:.1}\" y2=\"{:.1}\" stroke=\"{colour}\" stroke-width=\"2\"/>\n",
                    py(star * (-unc).exp()),
                    py(star * unc.exp())
                );
                s += &marker(b, x, py(star), colour, true);
                if let Some(f) = fine {
                    if (f / star - 1.0).abs() > 0.005 {
                        s += &marker(b, x, py(f), colour, false);
                    }
                }
            }
        }
    }
    // legend: white box, grey outline; each entry with its colour and marker
    let (lx, ly) = (w - right + 12.0, top + 4.0);
    s += &format!("<rect x=\"{lx}\" y=\"{ly}\" width=\"262\" height=\"150\" fill=\"white\" stroke=\"#8c8c8c\"/>\n");
    let mut y = ly + 22.0;
    for (name, colour, _) in &laws {
        s += &format!("<line x1=\"{}\" x2=\"{}\" y1=\"{y}\" y2=\"{y}\" stroke=\"{colour}\" stroke-width=\"3\"/>", lx + 10.0, lx + 40.0);
        s += &format!("<text x=\"{}\" y=\"{}\">{name}</text>\n", lx + 48.0, y + 5.0);
        y += 24.0;
    }
    s += &marker(1.125, lx + 25.0, y, "#444", true);
    s += &format!("<text x=\"{}\" y=\"{}\">beta = 9/8 (solid line)</text>\n", lx + 48.0, y + 5.0);
    y += 24.0;
    s += &marker(2.0, lx + 25.0, y, "#444", true);
    s += &format!("<text x=\"{}\" y=\"{}\">beta = 2 (dashed line)</text>\n", lx + 48.0, y + 5.0);
    y += 24.0;
    s += &marker(1.125, lx + 25.0, y, "#444", false);
    s += &format!("<text x=\"{}\" y=\"{}\">4096 cells, 400 steps</text>\n", lx + 48.0, y + 5.0);
    s += &format!(
        "<text x=\"{}\" y=\"{}\" font-size=\"12\">bars: bisection + grid shift</text>\n<text x=\"{}\" y=\"{}\" font-size=\"12\">(estimate 3.1 % where not measured)</text>\n",
        lx,
        ly + 172.0,
        lx,
        ly + 188.0
    );
    s += "</svg>\n";
    std::fs::write(&a[2], s).unwrap_or_else(|e| panic!("write {}: {e}", a[2]));
}
