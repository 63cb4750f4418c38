//! Command-line arguments that are not UTF-8. Paths are taken as the system gives them, but a
//! flag read as text (`--expr`, `--prim`, `--res`, …) cannot be, and clap then says only
//! "invalid UTF-8 was detected in one or more arguments". This finds which argument it is
//! and names its flag (or its positional's name), so the one-line error says what to fix.

use std::ffi::{OsStr, OsString};
use std::path::PathBuf;

use clap::{Arg, Command, CommandFactory};

/// The one-line message for the first argument of `args` (the program's name first) that is
/// not UTF-8 where csgpix reads text: `FLAG: the value "…" is not UTF-8 …`. None when there
/// is none (every argument is UTF-8, or only paths are not).
///
/// ```
/// use std::ffi::OsString;
/// use std::os::unix::ffi::OsStringExt;
///
/// let args: Vec<OsString> = ["csgpix", "blist", "--trace", "0,0,0"].map(OsString::from).into();
/// assert_eq!(csgpix_run::args_utf8::message(&args), None);
/// let mut args = args;
/// args.insert(2, OsString::from_vec(b"A\xff".to_vec()));
/// let m = csgpix_run::args_utf8::message(&args).unwrap();
/// assert!(m.starts_with(r#"EXPR: the value "A\xFF" is not UTF-8"#), "{m}");
/// ```
pub fn message(args: &[OsString]) -> Option<String> {
    let mut root = super::Cli::command();
    root.build();
    let scan = Scan::of(&root, args);
    let (arg, token, flag_len) = scan.owners.into_iter().find(|(arg, token, _)| {
        token.to_str().is_none() && !arg.as_ref().is_some_and(reads_os_strings)
    })?;
    let name = arg.as_ref().map_or_else(|| "an argument".to_string(), show);
    // The value without the flag it is attached to (`--res=`, `-o`), which is ASCII.
    let value = &token.as_encoded_bytes()[flag_len..];
    Some(format!(
        "{name}: the value {} is not UTF-8: csgpix reads it as text",
        shown(value)
    ))
}

/// The most bytes of a value a message quotes: a longer one is shown around its first byte
/// that is not UTF-8, so that a 100 kB argument is not a 100 kB line.
const SHOWN: usize = 64;

/// `value` quoted with its bytes that are not UTF-8 escaped (`"A\xFF"`); past [`SHOWN`]
/// bytes, [`SHOWN`] of them around the first such byte, with the value's length and that
/// byte's offset.
fn shown(value: &[u8]) -> String {
    let bad = std::str::from_utf8(value)
        .err()
        .map_or(0, |e| e.valid_up_to());
    // As `OsStr`'s Debug writes it: text escaped as Rust does, other bytes as `\xFF`.
    let quote = |b: &[u8]| {
        let mut q = String::new();
        for chunk in b.utf8_chunks() {
            q.extend(chunk.valid().chars().flat_map(char::escape_debug));
            for byte in chunk.invalid() {
                q += &format!("\\x{byte:02X}");
            }
        }
        q
    };
    if value.len() <= SHOWN {
        return format!("\"{}\"", quote(value));
    }
    let start = bad.saturating_sub(SHOWN / 2).min(value.len() - SHOWN);
    let (head, tail) = (start > 0, start + SHOWN < value.len());
    format!(
        "\"{}{}{}\" ({} bytes, the first not UTF-8 at byte {bad})",
        if head { "…" } else { "" },
        quote(&value[start..start + SHOWN]),
        if tail { "…" } else { "" },
        value.len()
    )
}

/// Whether the argument takes its value as the system gives it (a path).
fn reads_os_strings(arg: &Arg) -> bool {
    let ty = arg.get_value_parser().type_id();
    ty == std::any::TypeId::of::<PathBuf>() || ty == std::any::TypeId::of::<OsString>()
}

/// The argument as the command line spells it: `--expr`, `-o`, or a positional's `EXPR`.
fn show(arg: &Arg) -> String {
    match (arg.get_long(), arg.get_short()) {
        (Some(long), _) => format!("--{long}"),
        (None, Some(short)) => format!("-{short}"),
        (None, None) => arg
            .get_value_names()
            .and_then(|names| names.first())
            .map_or_else(
                || arg.get_id().to_string().to_uppercase(),
                |n| n.to_string(),
            ),
    }
}

/// Each value of the command line with the argument it belongs to, as clap would assign it,
/// and the length of the flag before it in the same word (`--res=`: 6).
struct Scan<'c> {
    owners: Vec<(Option<Arg>, &'c OsStr, usize)>,
}

impl<'c> Scan<'c> {
    fn of(root: &Command, args: &'c [OsString]) -> Scan<'c> {
        let mut owners = Vec::new();
        let mut cmd = root;
        let mut pending: Option<Arg> = None;
        let (mut positionals, mut only_positionals) = (0, false);
        for a in args.iter().skip(1) {
            let text = a.to_string_lossy();
            if let Some(flag) = pending.take() {
                owners.push((Some(flag), a.as_os_str(), 0));
            } else if std::ptr::eq(cmd, root) && root.find_subcommand(&*text).is_some() {
                cmd = root.find_subcommand(&*text).expect("found");
            } else if !only_positionals && text == "--" {
                only_positionals = true;
            } else if let Some((arg, attached)) = flag(cmd, &text).filter(|_| !only_positionals) {
                match (arg.get_action().takes_values(), attached) {
                    (true, true) => owners.push((Some(arg), a.as_os_str(), attached_at(&text))),
                    (true, false) => pending = Some(arg),
                    (false, _) => {}
                }
            } else {
                let arg = cmd
                    .get_positionals()
                    .nth(positionals)
                    .or(cmd.get_positionals().last());
                owners.push((arg.cloned(), a.as_os_str(), 0));
                positionals += 1;
            }
        }
        Scan { owners }
    }
}

/// The flag `text` names (`--long`, `--long=VALUE`, `-s`, `-sVALUE`) and whether its value is
/// attached to it; None for a positional (or an unknown flag, which clap reports itself).
fn flag(cmd: &Command, text: &str) -> Option<(Arg, bool)> {
    if let Some(long) = text.strip_prefix("--") {
        let (name, attached) = long
            .split_once('=')
            .map_or((long, false), |(n, _)| (n, true));
        let arg = cmd.get_arguments().find(|a| a.get_long() == Some(name))?;
        return Some((arg.clone(), attached));
    }
    let mut chars = text.strip_prefix('-')?.chars();
    let short = chars.next()?;
    let arg = cmd.get_arguments().find(|a| a.get_short() == Some(short))?;
    Some((arg.clone(), chars.next().is_some()))
}

/// Where an attached value starts: after `--long=`, or after `-s`.
fn attached_at(text: &str) -> usize {
    match text.strip_prefix("--") {
        Some(long) => 2 + long.find('=').map_or(long.len(), |i| i + 1),
        None => 1 + text[1..].chars().next().map_or(0, char::len_utf8),
    }
}
