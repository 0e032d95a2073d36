//! The `maugis` command line.
//!
//! * `maugis eval`: JSON Lines calculator over the special functions (see `eval.rs`).
//! * `maugis demo`: evaluates a few representative requests through `eval` and
//!   prints them (the quick-start main job until the Maugis solver lands).
//!
//! Usage errors exit with code 2 and a one-line message on stderr.

mod eval;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(name = "maugis", version, about = "Certified special functions for the wavy Maugis line contact")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// JSON Lines calculator: one request per stdin line, one response per stdout line.
    Eval,
    /// Show a few certified evaluations (the Eq. 12 building blocks at the model's arguments).
    Demo,
}

/// Requests of the demo: the Eq. 12 factors at abar = 6, beta = 9/8, and the edge x = a.
const DEMO_REQUESTS: &[&str] = &[
    r#"{"id":"J_5(2.5), 200 bits","fn":"bessel_j","n":5,"x":"2.5","prec":200}"#,
    r#"{"id":"1F2(1/2; 1, 3/2; -300), 128 bits","fn":"hyp1f2","a":0.5,"b1":1,"b2":1.5,"z":-300,"prec":128}"#,
    r#"{"id":"1F2(1/2; 1001, 1001.5; -300), 128 bits","fn":"hyp1f2","a":0.5,"b1":1001,"b2":1001.5,"z":-300,"prec":128}"#,
    r#"{"id":"2F1(1, 1000.5; 1002; 1), 128 bits","fn":"hyp2f1","a":1,"b":1000.5,"c":1002,"z":1,"prec":128}"#,
    r#"{"id":"G(1000, 1 - 1e-12), 128 bits","fn":"meijer_g_k","k":1000,"y":"0.999999999999","prec":128}"#,
    r#"{"id":"G(3, 1) (singular point), f64","fn":"meijer_g_k","k":3,"y":1}"#,
    r#"{"id":"bad request","fn":"meijer_g_k","k":3,"y":1.5}"#,
];

fn main() {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            std::process::exit(code);
        }
    };
    let code = match cli.command {
        Command::Eval => eval::run(),
        Command::Demo => {
            println!("maugis demo: certified evaluations through the `maugis eval` protocol\n");
            for req in DEMO_REQUESTS {
                println!("> {req}");
                println!("< {}\n", eval::handle_line(req));
            }
            println!("Try: echo '{{\"id\":1,\"fn\":\"bessel_j\",\"n\":5,\"x\":\"2.5\",\"prec\":200}}' | maugis eval");
            0
        }
    };
    std::process::exit(code);
}
