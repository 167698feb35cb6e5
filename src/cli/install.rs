//! What a package installs beside the binary, generated from the same clap
//! definition the binary parses with, so neither can drift from the options:
//! shell completions (`clap_complete`) and the man pages (`clap_mangen`); and
//! the playground's site this zsim carries, for a course's web server.

use std::io::Write;
use std::path::PathBuf;

use clap::{Args, CommandFactory};

use super::{Cli, Failure, Finish};

#[derive(Debug, Args)]
pub struct CompletionsArgs {
    /// The shell to complete zsim's commands and options in.
    #[arg(value_enum)]
    shell: clap_complete::Shell,
}

#[derive(Debug, Args)]
pub struct ManualArgs {
    /// A folder to write zsim.1 and one page per command (zsim-run.1, …) into; without it, zsim.1 goes to standard output.
    #[arg(long, value_name = "DIR")]
    dir: Option<PathBuf>,
}

#[derive(Debug, Args)]
pub struct PlaygroundArgs {
    /// The folder to write the site into (index.html and the files it loads): for any static web server, or opened from disk.
    #[arg(short, long, value_name = "DIR")]
    output: PathBuf,
}

/// Writes the playground's site into a folder (replacing an older one's files).
pub fn playground(lang: zsim::Lang, args: &PlaygroundArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let names = zsim::playground::write_site(&args.output).ok_or(super::flags::Flag::NoPlayground)??;
    let line = zsim::words!(lang, "file-written-in", files = names.join(", "), path = zsim::shown_path(&args.output));
    super::emit(out, &format!("{line}\n"))?;
    Ok(Finish::Ok)
}

/// Prints the completion script for one shell.
pub fn completions(args: &CompletionsArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let mut command = Cli::command();
    // Made whole first: clap_complete panics on a write that fails (`| true` closes the pipe).
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut command, "zsim", &mut script);
    out.write_all(&script)?;
    Ok(Finish::Ok)
}

/// Prints the man page, or writes every command's page into a folder.
pub fn manual(lang: zsim::Lang, args: &ManualArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let command = Cli::command();
    match &args.dir {
        None => clap_mangen::Man::new(command).render(out)?,
        Some(dir) => {
            let mut command = command.disable_help_subcommand(true);
            command.build();
            let mut pages = Vec::new();
            page_and_subpages(&command, &mut pages)?;
            zsim::write_fresh(dir, &pages, &[])?;
            let names: Vec<&str> = pages.iter().map(|(name, _)| name.as_str()).collect();
            let line = zsim::words!(lang, "file-written-in", files = names.join(", "), path = zsim::shown_path(dir));
            super::emit(out, &format!("{line}\n"))?;
        }
    }
    Ok(Finish::Ok)
}

/// The EXAMPLES section of command `name` (`zsim-buet-run`): the README's
/// and the guide's examples of it, which `cargo test` runs, at most eight.
fn examples(name: &str) -> String {
    let words: Vec<&str> = name.split('-').skip(1).collect();
    let of_it = |line: &&str| line.split(' ').take(words.len()).eq(words.iter().copied());
    let lines: Vec<&str> =
        include_str!(concat!(env!("OUT_DIR"), "/examples.txt")).lines().filter(of_it).take(8).collect();
    // The examples as the package installs them (`/usr/share/doc/zsim/examples`), so that each
    // runs from any folder; the guide's run from a clone, where they are `examples/`.
    let installed = |line: &str| line.replace(" examples/", " /usr/share/doc/zsim/examples/");
    // Roff: a backslash is written `\e`; a line may not start with `.` or `'` (it is after `zsim `).
    let body: String = lines
        .iter()
        .map(|line| format!("zsim {}\n", installed(line).replace('\\', "\\e").replace('-', "\\-")))
        .collect();
    if body.is_empty() { String::new() } else { format!(".SH EXAMPLES\n.nf\n{body}.fi\n") }
}

/// The man page of `command`, then those of its subcommands, named as man
/// names them (zsim.1, zsim-run.1, zsim-buet-run.1, …; clap sets these
/// display names when it builds the command).
fn page_and_subpages(command: &clap::Command, pages: &mut Vec<(String, Vec<u8>)>) -> Result<(), Failure> {
    let man = clap_mangen::Man::new(command.clone());
    let mut page = Vec::new();
    man.render(&mut page)?;
    let name = command.get_display_name().unwrap_or("zsim");
    page.extend(examples(name).into_bytes());
    // The stepper's keys, from the lesson's one table of them.
    if name == "zsim-step" {
        let keys = zsim::lesson::Command::keys_text(zsim::Lang::En).replace('\\', "\\e").replace('-', "\\-");
        page.extend(format!(".SH KEYS\n{keys}\n").into_bytes());
    }
    pages.push((man.get_filename(), page));
    for sub in command.get_subcommands().filter(|s| !s.is_hide_set()) {
        page_and_subpages(sub, pages)?;
    }
    Ok(())
}
