//! The command line: the only place that prints. Exit codes: 0 ok, 1 an
//! answer differs (`check`), 2 bad input or usage.

mod accuracy;
mod buet;
mod check;
mod course;
mod cs418;
mod exercise;
mod explain;
mod figure;
mod flags;
mod generate;
mod grade;
mod install;
mod run;
#[cfg(feature = "gpu")]
mod speed;
mod step;
mod tinyrenderer;
mod variants;

use std::io::{self, IsTerminal, Write};
use std::process::ExitCode;

use std::path::Path;

use clap::{Parser, Subcommand};
use zsim::Error;

/// Simulates the z-buffer hidden-surface algorithm exactly as the textbook teaches it.
#[derive(Debug, Parser)]
#[command(name = "zsim", version, about, max_term_width = 100)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// The language zsim explains in: en, ru, uk or zh (default: from LC_ALL, LC_MESSAGES or LANG, else English). Reports, explanations, figures and feedback speak it; --help, JSON, CSV and the files zsim writes for programs stay the same.
    #[arg(long, global = true, value_name = "LANG", value_parser = language)]
    lang: Option<zsim::Lang>,
}

fn language(code: &str) -> Result<zsim::Lang, String> {
    zsim::Lang::parse(code).ok_or_else(|| format!("\"{code}\" is not a language zsim speaks: use en, ru, uk or zh"))
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Draw a scene and print the framebuffer and z-buffer after each polygon.
    Run(run::RunArgs),
    /// Step through the algorithm one scanline at a time.
    Step(step::StepArgs),
    /// The history of one pixel through the whole scene.
    Explain(explain::ExplainArgs),
    /// Check a homework answer (a framebuffer and/or z-buffer) and explain every wrong cell.
    Check(check::CheckArgs),
    /// Make a new exercise: scene, worksheet, answer key, the hard cases it contains.
    Exercise(exercise::ExerciseArgs),
    /// Grade a class: every student's answers in a folder, the common mistakes, feedback files.
    Grade(grade::GradeArgs),
    /// A platform's grader (Gradescope, PrairieLearn) for one submission of a class with variants: results.json.
    Autograde(course::AutogradeArgs),
    /// Every arithmetic mode against exact: mismatches and time; a depth-bits sweep.
    Accuracy(accuracy::AccuracyArgs),
    /// Bits and bytes of the framebuffer and z-buffer for a raster.
    Memory(generate::MemoryArgs),
    /// Print a scene of random triangles (the same for the same seed).
    Random(generate::RandomArgs),
    /// BUET CSE 410 "Offline 2" cases: run, import, check.
    Buet(buet::BuetArgs),
    /// UIUC CS 418 rasterizer cases (rast-*.txt): run in the course's floats or exactly, compare, import.
    Cs418(cs418::Cs418Args),
    /// tinyrenderer's z-buffer lesson: run a model (OBJ) to the lesson's two TGA images, or import it as a scene.
    Tinyrenderer(tinyrenderer::TinyrendererArgs),
    /// Draw the raster as a figure, SVG, PNG, PDF or TikZ by the output's extension: grid, centres, scanlines, outlines, covered pixels.
    Figure(figure::FigureArgs),
    /// Time zsim beside the machine's OpenGL (Mesa's llvmpipe) on the same scene, in alternating pairs: medians and their ratio.
    #[cfg(feature = "gpu")]
    Speed(speed::SpeedArgs),
    /// Write the browser playground's site (the stepper, its quiz, the homework check) into a folder, for a static web server or to open from disk.
    Playground(install::PlaygroundArgs),
    /// Print the shell completion script for bash, zsh, fish, elvish or PowerShell.
    Completions(install::CompletionsArgs),
    /// Print zsim's man page (troff), or write one page per command into a folder.
    Manual(install::ManualArgs),
}

/// How a command ended, when it did not fail.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Finish {
    /// Everything fine: exit 0.
    Ok,
    /// An answer differs from zsim's: exit 1.
    Differs,
}

/// What can stop a command.
#[derive(Debug)]
pub enum Failure {
    /// Bad input: exit 2 with the message.
    Input(Error),
    /// Flags that do not go together: exit 2 with the message.
    Flag(flags::Flag),
    /// Writing the output failed (a closed pipe is not reported).
    Io(io::Error),
}

impl From<Error> for Failure {
    fn from(error: Error) -> Failure {
        Failure::Input(error)
    }
}

impl From<flags::Flag> for Failure {
    fn from(flag: flags::Flag) -> Failure {
        Failure::Flag(flag)
    }
}

impl From<io::Error> for Failure {
    fn from(error: io::Error) -> Failure {
        Failure::Io(error)
    }
}

/// Parses the arguments, runs the command and maps the outcome to an exit code.
pub fn main() -> ExitCode {
    // Mesa's Vulkan device-selection layer looks for a Wayland display and has libwayland print
    // "XDG_RUNTIME_DIR is invalid or not set" on a headless machine; zsim picks its adapter itself.
    if std::env::var_os("NODEVICE_SELECT").is_none() {
        // SAFETY: the process's first step, before any other thread starts.
        unsafe { std::env::set_var("NODEVICE_SELECT", "1") };
    }
    // The language first, so that a usage error is already in it.
    let lang = language_of_the_run();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(error) => return usage_error(lang, &error),
    };
    let lang = cli.lang.unwrap_or(lang);
    if stdout_is_closed() {
        // Rust's standard output drops writes to a closed descriptor silently.
        say(&zsim::words!(lang, "error-output", reason = zsim::words!(lang, "stdout-closed")));
        return ExitCode::from(2);
    }
    let stdout = io::stdout();
    let mut out = io::BufWriter::new(stdout.lock());
    let result = match cli.command {
        Command::Run(args) => run::run(lang, &args, &mut out),
        Command::Step(args) => step::run(lang, &args, &mut out),
        Command::Explain(args) => explain::run(lang, &args, &mut out),
        Command::Check(args) => check::run(lang, &args, &mut out),
        Command::Grade(args) if args.variants.is_some() => course::grade(lang, &args, &mut out),
        Command::Grade(args) => grade::run(lang, &args, &mut out),
        Command::Autograde(args) => course::autograde(lang, &args, &mut out),
        Command::Exercise(args) if args.roster.is_some() => course::exercise(lang, &args, &mut out),
        Command::Exercise(args) => exercise::run(lang, &args, &mut out),
        Command::Figure(args) => figure::run(lang, &args, &mut out),
        Command::Buet(args) => buet::run(lang, &args, &mut out),
        Command::Cs418(args) => cs418::run(lang, &args, &mut out),
        Command::Tinyrenderer(args) => tinyrenderer::run(lang, &args, &mut out),
        Command::Accuracy(args) => accuracy::run(lang, &args, &mut out),
        Command::Memory(args) => generate::memory_command(lang, &args, &mut out),
        Command::Random(args) => generate::random_command(lang, &args, &mut out),
        #[cfg(feature = "gpu")]
        Command::Speed(args) => speed::run(lang, &args, &mut out),
        Command::Playground(args) => install::playground(lang, &args, &mut out),
        Command::Completions(args) => install::completions(&args, &mut out),
        Command::Manual(args) => install::manual(lang, &args, &mut out),
    };
    // A reader that closed the pipe after the last write still gets the status.
    let result = result.and_then(|finish| match out.flush() {
        Err(error) if error.kind() != io::ErrorKind::BrokenPipe => Err(Failure::Io(error)),
        _ => Ok(finish),
    });
    match result {
        Ok(Finish::Ok) => ExitCode::SUCCESS,
        Ok(Finish::Differs) => ExitCode::from(1),
        Err(Failure::Io(error)) if error.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(Failure::Io(error)) => {
            say(&zsim::words!(lang, "error-output", reason = error.to_string()));
            ExitCode::from(2)
        }
        Err(Failure::Input(error)) => {
            // Messages quote the input (names, tokens): never let it steer the terminal.
            say(&zsim::printable(&error.message(lang)));
            ExitCode::from(2)
        }
        Err(Failure::Flag(flag)) => {
            say(&zsim::printable(&flag.message(lang)));
            ExitCode::from(2)
        }
    }
}

/// The language of this run as the command line and the environment ask
/// for it: what a value parser words its refusal in, since clap calls it
/// before the parsed `--lang` is there to pass.
fn language_of_the_run() -> zsim::Lang {
    language_asked().unwrap_or_else(zsim::Lang::from_env)
}

/// Says one line on standard error, `zsim: ` first; a standard error that
/// cannot be written to loses the line but never stops zsim (an `eprintln!`
/// would panic).
fn say(line: &str) {
    let _ = writeln!(io::stderr(), "zsim: {line}");
}

/// The `--lang` of the command line, read before clap parses it.
/// Arguments are read as the system gives them (`args_os`): a file name
/// that is not UTF-8 is an argument like any other, not a panic.
fn language_asked() -> Option<zsim::Lang> {
    let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    let text = |arg: &std::ffi::OsString| arg.to_str().map(str::to_owned);
    args.iter().enumerate().find_map(|(i, arg)| match text(arg)?.strip_prefix("--lang") {
        Some("") => args.get(i + 1).and_then(text).and_then(|code| zsim::Lang::parse(&code)),
        Some(rest) => rest.strip_prefix('=').and_then(zsim::Lang::parse),
        None => None,
    })
}

/// Reports a usage error: clap's own message (with the usage line) in
/// English; in another language one line in it, naming the argument and the
/// value, and where to read on. Help and the version print as clap prints them.
fn usage_error(lang: zsim::Lang, error: &clap::Error) -> ExitCode {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    let english = lang == zsim::Lang::En;
    let context = |kind| match error.get(kind) {
        Some(ContextValue::String(text)) => zsim::printable(text).into_owned(),
        Some(ContextValue::Strings(texts)) => zsim::printable(&texts.join(", ")).into_owned(),
        _ => String::new(),
    };
    let message = match error.kind() {
        _ if english || !error.use_stderr() => None,
        ErrorKind::MissingRequiredArgument => {
            Some(zsim::words!(lang, "usage-missing", args = context(ContextKind::InvalidArg)))
        }
        ErrorKind::InvalidValue | ErrorKind::ValueValidation => {
            let reason = std::error::Error::source(error).map(|source| source.to_string());
            Some(zsim::words!(
                lang,
                "usage-invalid-value",
                value = zsim::token(lang, &context(ContextKind::InvalidValue)),
                arg = context(ContextKind::InvalidArg),
                reason = reason.unwrap_or_else(|| context(ContextKind::ValidValue))
            ))
        }
        ErrorKind::UnknownArgument => {
            Some(zsim::words!(lang, "usage-unknown-argument", arg = context(ContextKind::InvalidArg)))
        }
        ErrorKind::InvalidSubcommand => {
            Some(zsim::words!(lang, "usage-unknown-command", name = context(ContextKind::InvalidSubcommand)))
        }
        ErrorKind::ArgumentConflict => Some(zsim::words!(
            lang,
            "usage-conflict",
            arg = context(ContextKind::InvalidArg),
            other = context(ContextKind::PriorArg)
        )),
        _ => None,
    };
    match message {
        Some(message) => {
            say(&format!("{message} ({})", zsim::words!(lang, "usage-see-help")));
            ExitCode::from(2)
        }
        None => {
            let _ = error.print();
            ExitCode::from(error.exit_code().clamp(0, 255) as u8)
        }
    }
}

/// A parser for one of the library's named choices (a gradebook's
/// identity column, a visibility): clap lists `names` and checks the value
/// against them; `parse` turns the one given into the choice.
fn choice<T: Clone + Send + Sync + 'static>(
    names: &'static [&'static str],
    parse: fn(&str) -> Option<T>,
) -> impl clap::builder::TypedValueParser<Value = T> {
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new(names).map(move |name| parse(&name).expect("clap checked the name"))
}

/// The library's rows under their headings, as the book's tables are printed.
fn table<const N: usize>(listed: zsim::report::Listed<N>) -> comfy_table::Table {
    let mut table = comfy_table::Table::new();
    table.load_style(comfy_table::presets::ASCII_MARKDOWN).set_header(listed.header);
    for row in listed.rows {
        table.add_row(row);
    }
    table
}

/// Whether to colour output: only on a terminal, and never with `NO_COLOR` set.
fn use_color() -> bool {
    io::stdout().is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

/// Writes a command's last text and ends with `finish`, also when the reader
/// has closed the pipe (`zsim check … | head`): the exit status says what
/// it would have said (1 for a wrong answer), as ripgrep's does.
fn emit_then(out: &mut dyn Write, text: &str, finish: Finish) -> Result<Finish, Failure> {
    match out.write_all(text.as_bytes()) {
        Err(error) if error.kind() != io::ErrorKind::BrokenPipe => Err(Failure::Io(error)),
        _ => Ok(finish),
    }
}

/// Writes text, turning a closed pipe into a quiet stop.
/// A JSON document on one line, as scripts read it.
fn json_line(json: &impl serde::Serialize) -> String {
    format!("{}\n", serde_json::to_string(json).expect("serializing plain data cannot fail"))
}

fn emit(out: &mut dyn Write, text: &str) -> Result<(), Failure> {
    out.write_all(text.as_bytes()).map_err(Failure::Io)
}

/// Prints `text`, or writes it to `output` (never one of `inputs`) and says
/// so: the `-o FILE` of the commands that print a scene.
pub(crate) fn emit_or_write(
    lang: zsim::Lang,
    out: &mut dyn Write,
    output: Option<&Path>,
    text: &str,
    inputs: &[&Path],
) -> Result<(), Failure> {
    let Some(path) = output else { return emit(out, text) };
    let mut plan = zsim::Plan::new(inputs, zsim::Replace::Allowed);
    plan.file(path, text);
    plan.write()?;
    emit(out, &format!("{}\n", zsim::words!(lang, "file-written", path = zsim::shown_path(path))))
}

/// Whether standard output was closed when zsim started (`zsim run SCENE
/// >&-`): everything written would be lost without an error. Rust's runtime
/// opens `/dev/null` in place of a closed standard descriptor before `main`,
/// which looks just like `1<>/dev/null` (Python's `subprocess.DEVNULL`), a
/// wanted sink; so descriptor 1 is looked at before the runtime starts, by
/// a function the system's loader runs first ([`started`]).
fn stdout_is_closed() -> bool {
    started::STDOUT_CLOSED.load(std::sync::atomic::Ordering::Relaxed)
}

/// What the process was started with, noted before Rust's runtime starts.
mod started {
    use std::sync::atomic::AtomicBool;

    /// Whether descriptor 1 was closed when the process started.
    pub static STDOUT_CLOSED: AtomicBool = AtomicBool::new(false);

    #[cfg(target_os = "linux")]
    extern "C" fn note_closed_stdout() {
        // SAFETY: F_GETFL only reads descriptor 1's flags; it changes nothing.
        let closed = unsafe { libc::fcntl(1, libc::F_GETFL) } == -1;
        STDOUT_CLOSED.store(closed, std::sync::atomic::Ordering::Relaxed);
    }

    /// Run by the loader with the program's other initializers, before `main`
    /// and before Rust's runtime replaces a closed descriptor.
    #[cfg(target_os = "linux")]
    #[used]
    #[unsafe(link_section = ".init_array")]
    static NOTE_CLOSED_STDOUT: extern "C" fn() = note_closed_stdout;
}
