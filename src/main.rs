//! The `zsim` command: parse the arguments, run, map errors to exit codes.
//! Two front ends render the library's facts here: the command line
//! (`cli/`, the only place that prints) and the full-screen app (`app/`,
//! which `zsim step` starts on a terminal).

mod app;
mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
