//! `maugis sweep` over a profile of many waves (issue 35): the amplitude axis scales
//! every `alpha_j` of the profile given by `--wave`, `--waves` or `--weierstrass`.
//!
//! * one wave `--wave 1,B` on the amplitude axis writes the CSV of `--axis alpha
//!   --beta B` byte for byte (the scale is the amplitude when `alpha_1 = 1`);
//! * a two-wave sweep in two shards merges into the unsharded sweep's files; the CSV,
//!   the JSON, the map (below its legend) and the report name every wave;
//! * shards of different profiles do not merge (exit 2, no files); one-wave shards
//!   merge as they did (their JSON carries no profile).
//! Bad sweep flags with waves: cli_waves.rs.

use crate::cli_waves::{maugis, Scratch};
use crate::render;

fn run_ok(args: &[&str]) -> String {
    let o = maugis(args);
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

const GRID: [&str; 12] = ["--lambda-min", "1", "--lambda-max", "6", "--lambda-n", "2", "--n", "3", "--amax", "6", "--points", "40"];
const TWO: [&str; 4] = ["--wave", "2*sqrt(2)/8,9/8", "--wave", "sqrt(2)/8,3/8"];

#[test]
fn one_wave_on_the_amplitude_axis_writes_the_alpha_axis_csv() {
    let (amp, alpha) = (Scratch::new("amp"), Scratch::new("alpha"));
    run_ok(&[&["sweep"][..], &GRID, &["--wave", "1,9/8", "--max", "0.7", "--out", amp.s()]].concat());
    run_ok(&[&["sweep"][..], &GRID, &["--axis", "alpha", "--beta", "9/8", "--max", "0.7", "--out", alpha.s()]].concat());
    let csv = amp.read("sweep.csv");
    assert!(csv.starts_with("index,lambda,value,alpha,beta,"), "{csv}");
    assert_eq!(csv, alpha.read("sweep.csv"));
    // --axis amplitude with --alpha/--beta is the same one-wave profile
    let flags = Scratch::new("flags");
    run_ok(&[&["sweep"][..], &GRID, &["--axis", "amplitude", "--alpha", "1", "--beta", "9/8", "--max", "0.7", "--out", flags.s()]].concat());
    assert_eq!(flags.read("sweep.csv"), csv);
    assert_eq!(flags.read("sweep.json"), amp.read("sweep.json"));
}

#[test]
fn a_two_wave_sweep_names_its_waves_and_its_shards_merge_to_the_whole() {
    let whole = Scratch::new("whole");
    let report = run_ok(&[&["sweep"][..], &GRID, &TWO, &["--out", whole.s()]].concat());
    assert!(report.contains("profile: 2 waves (alpha, beta) = (0.3536, 1.125) + (0.1768, 0.375), every amplitude times s in [0, 1]"), "{report}");
    let csv = whole.read("sweep.csv");
    assert!(csv.starts_with("index,lambda,value,alpha_1,beta_1,alpha_2,beta_2,instabilities,"), "{csv}");
    assert_eq!(csv.lines().count(), 7);
    let json: serde_json::Value = serde_json::from_str(&whole.read("sweep.json")).unwrap();
    assert_eq!(json["grid"]["axis"], "amplitude");
    assert_eq!(json["grid"]["profile"].as_array().map(Vec::len), Some(2));
    let svg = whole.read("sweep.svg");
    assert!(svg.contains("Regime map: amplitude scale s over log10 λ"), "title");
    for line in ["profile, every α_j times s:", "2 waves (α, β) =", "(0.3536, 1.125)", "+ (0.1768, 0.375)"] {
        assert!(svg.lines().any(|l| l.trim() == line), "the map does not list {line}");
    }
    render::check_svg(&whole.0.join("sweep.svg"));

    let (s1, s2, merged) = (Scratch::new("s1"), Scratch::new("s2"), Scratch::new("merged"));
    for (sh, dir) in [("1/2", &s1), ("2/2", &s2)] {
        run_ok(&[&["sweep"][..], &GRID, &TWO, &["--shard", sh, "--out", dir.s()]].concat());
    }
    run_ok(&["merge", s2.s(), s1.s(), "--out", merged.s()]);
    for f in ["sweep.csv", "sweep.json", "sweep.svg"] {
        assert_eq!(merged.read(f), whole.read(f), "{f}");
    }

    // a shard of another profile (the second wave at another wavelength) does not merge
    let other = Scratch::new("other");
    run_ok(&[&["sweep"][..], &GRID, &["--wave", "2*sqrt(2)/8,9/8", "--wave", "sqrt(2)/8,1/4", "--shard", "2/2", "--out", other.s()]].concat());
    let bad = Scratch::new("bad");
    let o = maugis(&["merge", s1.s(), other.s(), "--out", bad.s()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("different profiles"), "{err}");
    assert!(!bad.0.exists(), "a refused merge wrote files");
}

#[test]
fn one_wave_shards_carry_no_profile_and_merge_as_before() {
    let (s1, s2, merged) = (Scratch::new("o1"), Scratch::new("o2"), Scratch::new("omerged"));
    let grid = ["--lambda-min", "1", "--lambda-max", "6", "--lambda-n", "2", "--n", "2", "--points", "30"];
    for (sh, dir) in [("1/2", &s1), ("2/2", &s2)] {
        run_ok(&[&["sweep"][..], &grid, &["--shard", sh, "--out", dir.s()]].concat());
        assert!(!dir.read("sweep.json").contains("profile"), "a one-wave shard writes the old JSON");
    }
    run_ok(&["merge", s1.s(), s2.s(), "--out", merged.s()]);
    assert!(merged.read("sweep.csv").starts_with("index,lambda,value,alpha,beta,"));
}
