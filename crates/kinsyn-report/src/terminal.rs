//! What the commands show while they work, and the one-line form of their messages: progress
//! bars and a spinner on stderr (drawn only on a terminal), and [`one_line`], which errors and
//! warnings pass through (the command line prints them, `kinsyn-cli`'s `terminal`; Python
//! raises them).

/// `message` made safe for one line of a terminal: line breaks, escape sequences and every
/// other control or bidirectional-formatting character are written as Rust escapes (`\n`,
/// `\u{1b}`, `\u{202e}`), so that echoed input can neither add lines nor reorder or recolour
/// the text around it ([`kinsyn::markup::visible`]).
#[must_use]
pub fn one_line(message: &str) -> String {
    kinsyn::markup::visible(message).into_owned()
}

/// Runs `work` with a spinner and `message` on stderr, shown only when stderr is a terminal
/// (so that scripts and tests see nothing) and cleared when the work is done.
pub fn working<T>(message: &str, work: impl FnOnce() -> T) -> T {
    let spinner = indicatif::ProgressBar::new_spinner().with_message(message.to_string());
    spinner.enable_steady_tick(std::time::Duration::from_millis(120));
    let result = work();
    spinner.finish_and_clear();
    result
}

/// A progress bar over `count` items (`unit`: "paths", "lock subsets") on stderr, labelled
/// `message`. indicatif hides it (draws nothing) when stderr is not a terminal, so pipes, files
/// and tests see only the output and the errors.
#[must_use]
pub fn progress(count: usize, unit: &str, message: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(count as u64);
    if let Ok(style) = indicatif::ProgressStyle::with_template(&format!(
        "{{msg}} [{{bar:30}}] {{pos}}/{{len}} {unit}, {{elapsed}} elapsed, about {{eta}} left"
    )) {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(message.to_string());
    bar
}
