//! Bertini input files: the plain-text description of a polynomial system read by Bertini
//! (Bates, Hauenstein, Sommese & Wampler, *Numerically Solving Polynomial Systems with
//! Bertini*, SIAM 2013, ch. 5 and appendix E), and the common currency between numerical
//! algebraic geometry solvers.
//!
//! A file is an optional `CONFIG … END;` section of `key: value;` settings and an
//! `INPUT … END;` section declaring the unknowns and the equations:
//!
//! ```text
//! % the unit circle met by the line x = y
//! CONFIG
//!   TrackType: 0;
//! END;
//! INPUT
//!   variable_group x, y;
//!   function circle, line;
//!   constant r;
//!   r = 1;
//!   circle = x^2 + y^2 - r^2;
//!   line = x - y;
//! END;
//! ```
//!
//! [`parse`] reads such a file into a [`System`] (variables and equations in declaration
//! order, one variable group per `variable_group`), and [`write()`] writes a system back;
//! `parse(&write(s))` gives `s` again, coefficient for coefficient.
//!
//! What is read: declarations `variable_group`, `hom_variable_group` (projective
//! coordinates, recorded in [`BertiniInput::homogeneous_groups`]), `variable` (all such
//! variables one group), `function`, `constant`; assignments of functions, of constants (to
//! constant expressions), and of subfunctions (a name assigned without declaration);
//! expressions with `+ - * / ^`, parentheses, unary minus, decimal numbers in any float
//! notation, `I` (the imaginary unit) and `Pi`. Division only by constants, powers only with
//! constant non-negative integer exponents: anything else is not a polynomial and is refused,
//! as are `sin`, `exp` and the other functions. Every step of an expression is checked: a
//! product or power whose total degree would exceed [`MAX_DEGREE`] is refused before it is
//! expanded (degrees computed in `u64`, so they never wrap), and so is a value or coefficient
//! that becomes infinite or NaN in double precision (`1e308*1e308`, and so `(1e308*1e308)*0`).
//!
//! What reading may cost is bounded before the work is done, whatever the file: expressions
//! nest at most [`MAX_NESTING`] deep (parentheses, signs and powers; the reader's recursion
//! is one level per parenthesis, so its stack is bounded too); a product or power is refused
//! before it is multiplied when the bound on its terms exceeds [`MAX_TERMS`] or the bound on
//! its work exceeds what is left of the file's [`ExpansionBudget`] ([`expansion`]); at most
//! [`MAX_VARIABLES`] variables and [`MAX_EQUATIONS`] functions are declared. [`parse_program`]
//! reads a file and compiles its system's straight-line program: everything a solver builds
//! from the text before it tracks a path.
//! Refused with an explanation: `pathvariable` and `parameter` (Bertini's user-defined
//! homotopies: kinsyn's parameter homotopy takes its parameters as data of the family, not from
//! the file) and `random`/`random_real`
//! (constants drawn anew by every run: a file read twice would give two different systems;
//! write the drawn value as a `constant`).

use super::expansion::{self, ExpansionBudget, MAX_TERMS};
use super::{
    C64, MAX_DEGREE, MAX_EQUATIONS, MAX_PROGRAM_SIZE, MAX_VARIABLES, Poly, PolyError, System,
};
use std::collections::HashMap;
use std::fmt::Write as _;

/// The deepest nesting of an expression: parentheses, signs and powers written one inside
/// another (`((x))`, `- - x` and `x^1^1` each nest two deep). The reader descends one level
/// of its grammar per parenthesis and reads signs and chains of `^` in loops, so this bounds
/// its stack and the operands it holds at once. A level of parentheses takes about 2.7 KiB of
/// stack in the test build (256 levels needed between 640 and 768 KiB), so 128 levels fit in a
/// quarter of a test thread's 2 MiB; real files nest a handful.
pub const MAX_NESTING: usize = 128;

/// The most characters of an expression an error message quotes (then `…`).
const QUOTED_CHARS: usize = 60;

/// A Bertini input file as read by [`parse`].
#[derive(Clone, Debug, PartialEq)]
pub struct BertiniInput {
    /// The system: variables in declaration order, equations in the order of the `function`
    /// declaration, one variable group per `variable_group`/`hom_variable_group` line.
    pub system: System,
    /// The names of the equations (the declared functions), one per equation.
    pub functions: Vec<String>,
    /// The `CONFIG` settings in file order, `key: value;` as `(key, value)`, both trimmed and
    /// the value kept as written (Bertini's settings mean nothing to kinsyn's solver itself).
    pub config: Vec<(String, String)>,
    /// Whether some variable group was declared `hom_variable_group`: its variables are
    /// homogeneous coordinates of a projective space, not affine coordinates.
    pub homogeneous: bool,
    /// The indices (into [`System::groups`]) of the groups declared `hom_variable_group`.
    pub homogeneous_groups: Vec<usize>,
    /// The declared constants and their values, in declaration order.
    pub constants: Vec<(String, C64)>,
}

/// Why a Bertini input file cannot be read: where (1-based line) and what.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("line {line}: {kind}")]
pub struct BertiniError {
    /// The 1-based line of the offending text (for something missing, the line where it was
    /// due).
    pub line: usize,
    /// What is wrong.
    pub kind: BertiniErrorKind,
}

/// The kinds of [`BertiniError`].
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum BertiniErrorKind {
    /// A name that is neither declared nor assigned before its use.
    #[error("unknown name '{name}' in {context}")]
    UnknownName {
        /// The name.
        name: String,
        /// The function, constant or subfunction being defined.
        context: String,
    },
    /// An expression that is not a polynomial (a transcendental function, a variable in a
    /// denominator, a fractional or negative power).
    #[error("{found} in {context} is not polynomial: {why}")]
    NotPolynomial {
        /// What was found, as written.
        found: String,
        /// The function, constant or subfunction being defined.
        context: String,
        /// What kinsyn accepts instead.
        why: String,
    },
    /// A product or power whose total degree exceeds [`MAX_DEGREE`] (computed without
    /// overflow, in `u64`): refused where it is written, before it is expanded.
    #[error(
        "the degree of '{found}' in {context} is {degree}, beyond the limit of {MAX_DEGREE} (2^20)"
    )]
    Degree {
        /// The expression, as written.
        found: String,
        /// The function, constant or subfunction being defined.
        context: String,
        /// Its total degree.
        degree: u64,
    },
    /// A product, power or sum whose expansion would have more than [`MAX_TERMS`] terms
    /// (an upper bound, [`expansion`]): refused where it is written, before it is expanded.
    #[error(
        "expanding '{found}' in {context} would give {terms} terms, beyond the limit of {MAX_TERMS}"
    )]
    Terms {
        /// The expression, as written.
        found: String,
        /// The function, constant or subfunction being defined.
        context: String,
        /// Its terms (an upper bound for a product or power).
        terms: u128,
    },
    /// A product or power (or a copy of a long subfunction) whose expansion would take more
    /// term operations than the file has left ([`ExpansionBudget`]): refused before it is
    /// expanded.
    #[error(
        "expanding '{found}' in {context} would take {work} term products, beyond the {left} left of the {total} a file in {} may take (2^26 words of memory)",
        variables_text(*nvars)
    )]
    Work {
        /// The expression, as written.
        found: String,
        /// The function, constant or subfunction being defined.
        context: String,
        /// Its term products (an upper bound).
        work: u128,
        /// The term operations the file has left.
        left: u64,
        /// The term operations a file in this many variables may take.
        total: u64,
        /// The file's variables.
        nvars: usize,
    },
    /// Parentheses, signs and powers nested deeper than [`MAX_NESTING`].
    #[error(
        "{context} nests parentheses, signs and powers more than {MAX_NESTING} deep (the limit)"
    )]
    Nesting {
        /// The function, constant or subfunction being defined.
        context: String,
    },
    /// More variables than [`MAX_VARIABLES`] or functions than [`MAX_EQUATIONS`].
    #[error("{count} {what} declared, beyond the limit of {limit}")]
    Size {
        /// `variables` or `functions`.
        what: &'static str,
        /// How many are declared (at least).
        count: usize,
        /// The limit.
        limit: usize,
    },
    /// A system whose straight-line program would exceed [`MAX_PROGRAM_SIZE`]
    /// ([`System::program_size`]).
    #[error(
        "the system's program of values and Jacobian would hold up to {size} factors, beyond the limit of {MAX_PROGRAM_SIZE}"
    )]
    ProgramSize {
        /// The bound on its size.
        size: u128,
    },
    /// An expression whose value (or a coefficient of its expansion) is infinite or NaN in
    /// double precision: an overflow such as `1e308*1e308`, or what follows from one
    /// (`(1e308*1e308)*0` is NaN).
    #[error("'{found}' in {context} is not finite in double precision (infinite or NaN)")]
    NotFinite {
        /// The expression, as written.
        found: String,
        /// The function, constant or subfunction being defined.
        context: String,
    },
    /// A Bertini construct kinsyn does not read, with the reason.
    #[error("{0}")]
    Unsupported(String),
    /// Text that is not Bertini's grammar.
    #[error("{0}")]
    Syntax(String),
    /// A name declared twice, assigned twice, or a declaration that is never completed.
    #[error("{0}")]
    Declaration(String),
    /// The variables and functions do not form a system.
    #[error("{0}")]
    System(PolyError),
}

/// `1 variable`, `3 variables`.
fn variables_text(n: usize) -> String {
    format!("{n} variable{}", if n == 1 { "" } else { "s" })
}

fn err(line: usize, kind: BertiniErrorKind) -> BertiniError {
    BertiniError { line, kind }
}

fn syntax(line: usize, message: impl Into<String>) -> BertiniError {
    err(line, BertiniErrorKind::Syntax(message.into()))
}

/// Bertini's functions of one argument: not polynomial.
const TRANSCENDENTAL: [&str; 12] = [
    "sin", "cos", "tan", "exp", "log", "sqrt", "asin", "acos", "atan", "sinh", "cosh", "tanh",
];

/// The declaration keywords (and other words a name may not be).
const KEYWORDS: [&str; 11] = [
    "variable_group",
    "hom_variable_group",
    "variable",
    "function",
    "constant",
    "parameter",
    "pathvariable",
    "random",
    "random_real",
    "subfunction",
    "END",
];

/// Whether `name` can name a variable in a Bertini file (and in [`write()`]'s output as is):
/// an identifier, not a keyword, not `I`, `Pi` or a function name.
#[must_use]
pub fn is_valid_name(name: &str) -> bool {
    let mut chars = name.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !reserved(name)
}

fn reserved(name: &str) -> bool {
    name == "I"
        || name == "Pi"
        || name == "CONFIG"
        || name == "INPUT"
        || KEYWORDS.contains(&name)
        || TRANSCENDENTAL.contains(&name)
}

// ---------------------------------------------------------------------------------------
// Lexing

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Name(String),
    Number(f64, String),
    Sym(char),
}

#[derive(Clone, Debug)]
struct Token {
    tok: Tok,
    line: usize,
}

impl Token {
    fn describe(&self) -> String {
        match &self.tok {
            Tok::Name(s) | Tok::Number(_, s) => format!("'{s}'"),
            Tok::Sym(c) => format!("'{c}'"),
        }
    }
}

/// The tokens of one statement (`text` starts on line `line`).
fn lex(text: &str, mut line: usize) -> Result<Vec<Token>, BertiniError> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut k = 0;
    while k < bytes.len() {
        let c = bytes[k];
        if c == b'\n' {
            line += 1;
            k += 1;
        } else if c.is_ascii_whitespace() {
            k += 1;
        } else if c.is_ascii_alphabetic() || c == b'_' {
            let start = k;
            while k < bytes.len() && (bytes[k].is_ascii_alphanumeric() || bytes[k] == b'_') {
                k += 1;
            }
            out.push(Token {
                tok: Tok::Name(text[start..k].to_string()),
                line,
            });
        } else if c.is_ascii_digit()
            || (c == b'.' && bytes.get(k + 1).is_some_and(u8::is_ascii_digit))
        {
            let start = k;
            while k < bytes.len() && bytes[k].is_ascii_digit() {
                k += 1;
            }
            if k < bytes.len() && bytes[k] == b'.' {
                k += 1;
                while k < bytes.len() && bytes[k].is_ascii_digit() {
                    k += 1;
                }
            }
            if k < bytes.len() && (bytes[k] == b'e' || bytes[k] == b'E') {
                let mut j = k + 1;
                if j < bytes.len() && (bytes[j] == b'+' || bytes[j] == b'-') {
                    j += 1;
                }
                if j < bytes.len() && bytes[j].is_ascii_digit() {
                    while j < bytes.len() && bytes[j].is_ascii_digit() {
                        j += 1;
                    }
                    k = j;
                }
            }
            let s = &text[start..k];
            if k < bytes.len() && (bytes[k].is_ascii_alphabetic() || bytes[k] == b'_') {
                return Err(syntax(
                    line,
                    format!(
                        "'{s}' followed by a name: write products with '*' (e.g. '{s}*{}')",
                        char::from(bytes[k])
                    ),
                ));
            }
            let v: f64 = s
                .parse()
                .map_err(|_| syntax(line, format!("'{s}' is not a number")))?;
            if !v.is_finite() {
                return Err(syntax(
                    line,
                    format!("'{s}' is beyond the range of double precision"),
                ));
            }
            out.push(Token {
                tok: Tok::Number(v, s.to_string()),
                line,
            });
        } else if b"+-*/^(),=:".contains(&c) {
            out.push(Token {
                tok: Tok::Sym(char::from(c)),
                line,
            });
            k += 1;
        } else {
            let ch = text[k..].chars().next().unwrap_or('?');
            return Err(syntax(line, format!("unexpected character '{ch}'")));
        }
    }
    Ok(out)
}

// ---------------------------------------------------------------------------------------
// Statements

/// One `;`-terminated statement: its text and the line where the text starts.
struct Statement<'a> {
    text: &'a str,
    line: usize,
}

/// The text with comments (`%` to the end of the line) blanked out, byte for byte.
fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut in_comment = false;
    for c in text.chars() {
        if c == '\n' {
            in_comment = false;
            out.push('\n');
        } else if in_comment || c == '%' {
            in_comment = true;
            for _ in 0..c.len_utf8() {
                out.push(' ');
            }
        } else {
            out.push(c);
        }
    }
    out
}

/// Splits at `;`, trimming each statement; a non-blank tail without `;` is an error.
fn statements(text: &str) -> Result<Vec<Statement<'_>>, BertiniError> {
    let mut out = Vec::new();
    let mut line = 1;
    for piece in text.split_inclusive(';') {
        let lead = piece.len() - piece.trim_start().len();
        let start_line = line + piece[..lead].matches('\n').count();
        line += piece.matches('\n').count();
        match piece.strip_suffix(';') {
            Some(body) => out.push(Statement {
                text: body.trim(),
                line: start_line,
            }),
            None if piece.trim().is_empty() => {}
            None => {
                return Err(syntax(
                    start_line,
                    format!("'{}' is not ended by ';'", first_words(piece.trim())),
                ));
            }
        }
    }
    Ok(out)
}

fn first_words(s: &str) -> String {
    let one_line = s.lines().next().unwrap_or("");
    if one_line.len() > 40 {
        let mut end = 40;
        while !one_line.is_char_boundary(end) {
            end -= 1;
        }
        format!("{}…", &one_line[..end])
    } else {
        one_line.to_string()
    }
}

/// Strips a leading section keyword (`CONFIG`/`INPUT` without its own `;`).
fn strip_keyword<'a>(s: &Statement<'a>, keyword: &str) -> Option<Statement<'a>> {
    let rest = s.text.strip_prefix(keyword)?;
    if rest
        .chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphanumeric() || c == '_')
    {
        return None;
    }
    let lead = rest.len() - rest.trim_start().len();
    Some(Statement {
        text: rest.trim_start(),
        line: s.line + rest[..lead].matches('\n').count(),
    })
}

/// Reads a Bertini input file.
///
/// # Errors
/// A [`BertiniError`] naming the 1-based line and what is wrong there: a name neither
/// declared nor assigned, a non-polynomial expression, an unsupported construct (parameters,
/// `pathvariable`, `random`), a syntax error, a repeated or incomplete declaration, or
/// variables and functions that do not form a system (e.g. a repeated variable).
pub fn parse(text: &str) -> Result<BertiniInput, BertiniError> {
    #[derive(PartialEq)]
    enum State {
        Start,
        Config,
        AfterConfig,
        Input,
        Done,
    }
    let clean = strip_comments(text);
    let total_lines = text.lines().count().max(1);
    let mut config = Vec::new();
    let mut reader = InputReader::default();
    let mut state = State::Start;
    for st in statements(&clean)? {
        match state {
            State::Start | State::AfterConfig => {
                if state == State::Start
                    && let Some(rest) = strip_keyword(&st, "CONFIG")
                {
                    state = State::Config;
                    if rest.text == "END" {
                        state = State::AfterConfig;
                    } else if !rest.text.is_empty() {
                        config.push(config_entry(&rest)?);
                    }
                } else if let Some(rest) = strip_keyword(&st, "INPUT") {
                    state = State::Input;
                    if rest.text == "END" {
                        state = State::Done;
                    } else if !rest.text.is_empty() {
                        reader.statement(&rest)?;
                    }
                } else {
                    return Err(syntax(
                        st.line,
                        format!(
                            "expected 'CONFIG' or 'INPUT', found '{}'",
                            first_words(st.text)
                        ),
                    ));
                }
            }
            State::Config => {
                if st.text == "END" {
                    state = State::AfterConfig;
                } else {
                    config.push(config_entry(&st)?);
                }
            }
            State::Input => {
                if st.text == "END" {
                    state = State::Done;
                } else {
                    reader.statement(&st)?;
                }
            }
            State::Done => {
                return Err(syntax(
                    st.line,
                    format!("'{}' after the INPUT section's END", first_words(st.text)),
                ));
            }
        }
    }
    match state {
        State::Done => reader.finish(config, total_lines),
        State::Config => Err(syntax(total_lines, "the CONFIG section has no 'END;'")),
        State::Input => Err(syntax(total_lines, "the INPUT section has no 'END;'")),
        State::Start | State::AfterConfig => Err(syntax(total_lines, "no 'INPUT … END;' section")),
    }
}

/// Reads a Bertini input file ([`parse`]) and compiles its system's straight-line program of
/// values and Jacobian ([`System::program`]): the text taken as far as a solver takes it before
/// tracking, at a cost bounded by the limits of this module whatever the text.
///
/// # Errors
/// As [`parse`]; [`BertiniErrorKind::ProgramSize`] for a system whose program would exceed
/// [`MAX_PROGRAM_SIZE`].
pub fn parse_program(text: &str) -> Result<(BertiniInput, super::Program), BertiniError> {
    let input = parse(text)?;
    let size = input.system.program_size();
    if size > MAX_PROGRAM_SIZE {
        return Err(err(
            text.lines().count().max(1),
            BertiniErrorKind::ProgramSize { size },
        ));
    }
    let program = input.system.program();
    Ok((input, program))
}

fn config_entry(st: &Statement<'_>) -> Result<(String, String), BertiniError> {
    let Some((key, value)) = st.text.split_once(':') else {
        return Err(syntax(
            st.line,
            format!(
                "CONFIG setting '{}' is not 'key: value;'",
                first_words(st.text)
            ),
        ));
    };
    let key = key.trim();
    let value = value.trim();
    let valid = !key.is_empty() && key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !valid || value.is_empty() {
        return Err(syntax(
            st.line,
            format!(
                "CONFIG setting '{}' is not 'key: value;'",
                first_words(st.text)
            ),
        ));
    }
    Ok((key.to_string(), value.to_string()))
}

// ---------------------------------------------------------------------------------------
// The INPUT section

#[derive(Clone, Copy, Debug, PartialEq)]
enum GroupKind {
    Affine,
    Homogeneous,
    Plain,
}

#[derive(Clone, Debug)]
enum Name {
    Variable(usize),
    Function(usize),
    Constant(usize),
    Subfunction(Poly),
}

#[derive(Default)]
struct InputReader {
    variables: Vec<String>,
    groups: Vec<(GroupKind, Vec<usize>)>,
    /// The group of the `variable` declarations, once there is one.
    plain_group: Option<usize>,
    functions: Vec<(String, usize, Option<Poly>)>,
    constants: Vec<(String, usize, Option<C64>)>,
    names: HashMap<String, Name>,
    /// Whether an assignment has been read (variables must be declared before).
    assigned: bool,
    /// What the expansions of the file may still take.
    budget: ExpansionBudget,
}

impl InputReader {
    fn statement(&mut self, st: &Statement<'_>) -> Result<(), BertiniError> {
        let tokens = lex(st.text, st.line)?;
        let Some(first) = tokens.first() else {
            return Err(syntax(st.line, "an empty statement (';' alone)"));
        };
        let Tok::Name(word) = &first.tok else {
            return Err(syntax(
                first.line,
                format!("a statement cannot start with {}", first.describe()),
            ));
        };
        let is_assignment = tokens.get(1).is_some_and(|t| t.tok == Tok::Sym('='));
        if is_assignment {
            return self.assignment(word, first.line, &tokens[2..]);
        }
        match word.as_str() {
            "variable_group" | "hom_variable_group" | "variable" | "function" | "constant" => {
                self.declaration(word, first.line, &tokens[1..])
            }
            "parameter" | "pathvariable" => Err(err(
                first.line,
                BertiniErrorKind::Unsupported(format!(
                    "'{word}' (Bertini's user-defined homotopy) is not supported: kinsyn's \
                     parameter homotopy takes the parameters of a family as data, not as \
                     functions of a path variable in the file"
                )),
            )),
            "random" | "random_real" => Err(err(
                first.line,
                BertiniErrorKind::Unsupported(format!(
                    "'{word}' constants are not supported (each run would draw another \
                     system): declare a 'constant' and write the value"
                )),
            )),
            _ => Err(syntax(
                first.line,
                format!("expected a declaration or 'name = expression', found '{word}'"),
            )),
        }
    }

    fn declare(&mut self, name: &str, line: usize, what: Name) -> Result<(), BertiniError> {
        if reserved(name) {
            return Err(err(
                line,
                BertiniErrorKind::Declaration(format!(
                    "'{name}' is reserved and cannot be declared"
                )),
            ));
        }
        if self.names.contains_key(name) {
            return Err(err(
                line,
                BertiniErrorKind::Declaration(format!("'{name}' is declared twice")),
            ));
        }
        self.names.insert(name.to_string(), what);
        Ok(())
    }

    fn declaration(&mut self, word: &str, line: usize, rest: &[Token]) -> Result<(), BertiniError> {
        // A comma-separated list of names.
        let mut list = Vec::new();
        for (k, t) in rest.iter().enumerate() {
            match (&t.tok, k % 2) {
                (Tok::Name(n), 0) => list.push((n.clone(), t.line)),
                (Tok::Sym(','), 1) => {}
                _ => {
                    return Err(syntax(
                        t.line,
                        format!(
                            "'{word}' expects names separated by ',', found {}",
                            t.describe()
                        ),
                    ));
                }
            }
        }
        if list.is_empty() || rest.len().is_multiple_of(2) {
            return Err(syntax(line, format!("'{word}' expects a list of names")));
        }
        match word {
            "variable_group" | "hom_variable_group" | "variable" => {
                let kind = match word {
                    "variable_group" => GroupKind::Affine,
                    "hom_variable_group" => GroupKind::Homogeneous,
                    _ => GroupKind::Plain,
                };
                if self.assigned {
                    return Err(err(
                        line,
                        BertiniErrorKind::Declaration(
                            "variables must be declared before the first assignment".into(),
                        ),
                    ));
                }
                let mixes = self
                    .groups
                    .iter()
                    .any(|(k, _)| (*k == GroupKind::Plain) != (kind == GroupKind::Plain));
                if mixes {
                    return Err(err(
                        line,
                        BertiniErrorKind::Declaration(
                            "'variable' and 'variable_group' cannot both be used".into(),
                        ),
                    ));
                }
                let group = if let (GroupKind::Plain, Some(g)) = (kind, self.plain_group) {
                    g
                } else {
                    self.groups.push((kind, Vec::new()));
                    if kind == GroupKind::Plain {
                        self.plain_group = Some(self.groups.len() - 1);
                    }
                    self.groups.len() - 1
                };
                check_size(
                    "variables",
                    self.variables.len() + list.len(),
                    MAX_VARIABLES,
                    line,
                )?;
                for (n, l) in list {
                    let index = self.variables.len();
                    self.declare(&n, l, Name::Variable(index))?;
                    self.variables.push(n);
                    self.groups[group].1.push(index);
                }
            }
            "function" => {
                check_size(
                    "functions",
                    self.functions.len() + list.len(),
                    MAX_EQUATIONS,
                    line,
                )?;
                for (n, l) in list {
                    self.declare(&n, l, Name::Function(self.functions.len()))?;
                    self.functions.push((n, l, None));
                }
            }
            _ => {
                for (n, l) in list {
                    self.declare(&n, l, Name::Constant(self.constants.len()))?;
                    self.constants.push((n, l, None));
                }
            }
        }
        Ok(())
    }

    fn assignment(&mut self, name: &str, line: usize, rhs: &[Token]) -> Result<(), BertiniError> {
        if reserved(name) {
            return Err(syntax(
                line,
                format!("'{name}' is reserved and cannot be assigned"),
            ));
        }
        self.assigned = true;
        let mut parser = ExprParser {
            tokens: rhs,
            pos: 0,
            reader: self,
            context: name,
            line,
            depth: 0,
        };
        let value = parser.expression()?;
        if let Some(t) = rhs.get(parser.pos) {
            let previous = parser.pos.checked_sub(1).map_or(line, |p| rhs[p].line);
            if t.line > previous {
                return Err(syntax(
                    previous,
                    format!(
                        "missing ';' at the end of {name}'s definition (found {} on line {})",
                        t.describe(),
                        t.line
                    ),
                ));
            }
            return Err(syntax(
                t.line,
                format!(
                    "unexpected {} in {name} (a missing operator?)",
                    t.describe()
                ),
            ));
        }
        let redefined = || {
            err(
                line,
                BertiniErrorKind::Declaration(format!("'{name}' is assigned twice")),
            )
        };
        match self.names.get(name).cloned() {
            Some(Name::Variable(_)) => Err(err(
                line,
                BertiniErrorKind::Declaration(format!(
                    "'{name}' is a variable and cannot be assigned"
                )),
            )),
            Some(Name::Function(k)) => {
                let slot = &mut self.functions[k].2;
                if slot.is_some() {
                    return Err(redefined());
                }
                *slot = Some(value);
                Ok(())
            }
            Some(Name::Constant(k)) => {
                let Some(c) = constant_value(&value) else {
                    return Err(err(
                        line,
                        BertiniErrorKind::Declaration(format!(
                            "constant '{name}' is assigned an expression in the variables"
                        )),
                    ));
                };
                let slot = &mut self.constants[k].2;
                if slot.is_some() {
                    return Err(redefined());
                }
                *slot = Some(c);
                Ok(())
            }
            Some(Name::Subfunction(_)) => Err(redefined()),
            None => {
                self.names
                    .insert(name.to_string(), Name::Subfunction(value));
                Ok(())
            }
        }
    }

    fn finish(
        self,
        config: Vec<(String, String)>,
        last_line: usize,
    ) -> Result<BertiniInput, BertiniError> {
        if self.variables.is_empty() {
            return Err(err(
                last_line,
                BertiniErrorKind::Declaration("no variables declared".into()),
            ));
        }
        if self.functions.is_empty() {
            return Err(err(
                last_line,
                BertiniErrorKind::Declaration("no functions declared".into()),
            ));
        }
        let mut constants = Vec::with_capacity(self.constants.len());
        for (n, l, v) in self.constants {
            let Some(v) = v else {
                return Err(err(
                    l,
                    BertiniErrorKind::Declaration(format!("constant '{n}' is never assigned")),
                ));
            };
            constants.push((n, v));
        }
        let mut names = Vec::with_capacity(self.functions.len());
        let mut equations = Vec::with_capacity(self.functions.len());
        for (n, l, p) in self.functions {
            let Some(p) = p else {
                return Err(err(
                    l,
                    BertiniErrorKind::Declaration(format!("function '{n}' is never defined")),
                ));
            };
            names.push(n);
            equations.push(p);
        }
        let homogeneous_groups: Vec<usize> = self
            .groups
            .iter()
            .enumerate()
            .filter(|(_, (k, _))| *k == GroupKind::Homogeneous)
            .map(|(j, _)| j)
            .collect();
        let groups = self.groups.into_iter().map(|(_, g)| g).collect();
        let system = System::new(self.variables, equations)
            .and_then(|s| s.with_groups(groups))
            .map_err(|e| err(last_line, BertiniErrorKind::System(e)))?;
        Ok(BertiniInput {
            system,
            functions: names,
            config,
            homogeneous: !homogeneous_groups.is_empty(),
            homogeneous_groups,
            constants,
        })
    }
}

/// The error for `count` declared `what`s, if beyond `limit`.
fn check_size(
    what: &'static str,
    count: usize,
    limit: usize,
    line: usize,
) -> Result<(), BertiniError> {
    if count <= limit {
        return Ok(());
    }
    Err(err(line, BertiniErrorKind::Size { what, count, limit }))
}

/// The value of a polynomial without variables (`None` if it has any).
fn constant_value(p: &Poly) -> Option<C64> {
    let mut value = C64::new(0.0, 0.0);
    for (e, c) in p.terms() {
        if e.iter().any(|k| *k != 0) {
            return None;
        }
        value = c;
    }
    Some(value)
}

// ---------------------------------------------------------------------------------------
// Expressions

struct ExprParser<'a> {
    tokens: &'a [Token],
    pos: usize,
    reader: &'a InputReader,
    context: &'a str,
    line: usize,
    /// The levels of nesting around the current position: parentheses, signs and `^`
    /// (at most [`MAX_NESTING`]).
    depth: usize,
}

impl ExprParser<'_> {
    fn nvars(&self) -> usize {
        self.reader.variables.len()
    }

    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.pos)
    }

    fn peek_sym(&self, c: char) -> bool {
        self.peek().is_some_and(|t| t.tok == Tok::Sym(c))
    }

    fn current_line(&self) -> usize {
        self.peek()
            .or_else(|| self.tokens.last())
            .map_or(self.line, |t| t.line)
    }

    fn not_polynomial(&self, line: usize, found: String, why: &str) -> BertiniError {
        err(
            line,
            BertiniErrorKind::NotPolynomial {
                found,
                context: self.context.to_string(),
                why: why.to_string(),
            },
        )
    }

    /// `p` if every coefficient is finite; else the error naming the expression from `start`
    /// to here (the first place where a value overflowed or became NaN).
    fn finite(&self, p: Poly, start: usize, line: usize) -> Result<Poly, BertiniError> {
        if p.is_finite() {
            Ok(p)
        } else {
            Err(self.not_finite(start, line))
        }
    }

    fn not_finite(&self, start: usize, line: usize) -> BertiniError {
        err(
            line,
            BertiniErrorKind::NotFinite {
                found: self.source(start, self.pos),
                context: self.context.to_string(),
            },
        )
    }

    /// The error for an expression from `start` to `end` of total degree `degree`, if it
    /// exceeds [`MAX_DEGREE`].
    fn degree_within_limit(
        &self,
        degree: u64,
        (start, end): (usize, usize),
        line: usize,
    ) -> Result<(), BertiniError> {
        if degree <= u64::from(MAX_DEGREE) {
            return Ok(());
        }
        Err(err(
            line,
            BertiniErrorKind::Degree {
                found: self.source(start, end),
                context: self.context.to_string(),
                degree,
            },
        ))
    }

    /// Spends `work` term operations of the file's budget, or the error naming the expression
    /// from `start` to `end` that would exceed it.
    fn spend(
        &self,
        work: u128,
        (start, end): (usize, usize),
        line: usize,
    ) -> Result<(), BertiniError> {
        let n = self.nvars();
        self.reader.budget.spend(work, n).map_err(|left| {
            err(
                line,
                BertiniErrorKind::Work {
                    found: self.source(start, end),
                    context: self.context.to_string(),
                    work,
                    left,
                    total: ExpansionBudget::total_terms(n),
                    nvars: n,
                },
            )
        })
    }

    /// Checks a product or power before it is expanded: its degree, its terms and its work
    /// ([`expansion`]); `span` is the expression as written.
    fn before_expanding(
        &self,
        degree: u64,
        estimate: expansion::Estimate,
        span: (usize, usize),
        line: usize,
    ) -> Result<(), BertiniError> {
        self.degree_within_limit(degree, span, line)?;
        self.terms_within_limit(estimate.terms, span, line)?;
        self.spend(estimate.work, span, line)
    }

    /// The error for an expression from `start` to `end` of (at most) `terms` terms, if that
    /// exceeds [`MAX_TERMS`].
    fn terms_within_limit(
        &self,
        terms: u128,
        (start, end): (usize, usize),
        line: usize,
    ) -> Result<(), BertiniError> {
        if terms <= MAX_TERMS as u128 {
            return Ok(());
        }
        Err(err(
            line,
            BertiniErrorKind::Terms {
                found: self.source(start, end),
                context: self.context.to_string(),
                terms,
            },
        ))
    }

    /// `acc ± rhs`, in place: the sum's new coefficients checked finite and its terms against
    /// [`MAX_TERMS`], the terms of `rhs` spent.
    fn add(
        &self,
        mut acc: Poly,
        rhs: Poly,
        negate: bool,
        start: usize,
        line: usize,
    ) -> Result<Poly, BertiniError> {
        self.spend(rhs.len() as u128, (start, self.pos), line)?;
        let rhs = if negate { -rhs } else { rhs };
        if !acc.add_assign_finite(rhs) {
            return Err(self.not_finite(start, line));
        }
        self.terms_within_limit(acc.len() as u128, (start, self.pos), line)?;
        Ok(acc)
    }

    fn expression(&mut self) -> Result<Poly, BertiniError> {
        let start = self.pos;
        let line = self.current_line();
        let mut acc = self.term()?;
        loop {
            let negate = if self.peek_sym('+') {
                false
            } else if self.peek_sym('-') {
                true
            } else {
                return Ok(acc);
            };
            self.pos += 1;
            let rhs = self.term()?;
            acc = self.add(acc, rhs, negate, start, line)?;
        }
    }

    fn term(&mut self) -> Result<Poly, BertiniError> {
        let start = self.pos;
        let line = self.current_line();
        let mut acc = self.unary()?;
        loop {
            if self.peek_sym('*') {
                self.pos += 1;
                let rhs = self.unary()?;
                let degree = u64::from(acc.total_degree()) + u64::from(rhs.total_degree());
                let estimate = expansion::product(&acc, &rhs);
                self.before_expanding(degree, estimate, (start, self.pos), line)?;
                acc = self.finite(acc * rhs, start, line)?;
            } else if self.peek_sym('/') {
                let line = self.current_line();
                self.pos += 1;
                let start = self.pos;
                let d = self.unary()?;
                match constant_value(&d) {
                    None => {
                        return Err(self.not_polynomial(
                            line,
                            format!("division by '{}'", self.source(start, self.pos)),
                            "only constant denominators are allowed",
                        ));
                    }
                    Some(c) if c == C64::new(0.0, 0.0) => {
                        return Err(syntax(
                            line,
                            format!(
                                "division by zero ('{}') in {}",
                                self.source(start, self.pos),
                                self.context
                            ),
                        ));
                    }
                    Some(c) => {
                        self.spend(acc.len() as u128, (start, self.pos), line)?;
                        acc = self.finite(divide(&acc, c), start, line)?;
                    }
                }
            } else {
                return Ok(acc);
            }
        }
    }

    /// The tokens from `start` to `end`, as written (spaced), shortened to about
    /// [`QUOTED_CHARS`] characters with `…`: an error message quotes it, and stays one short
    /// line whatever the expression.
    fn source(&self, start: usize, end: usize) -> String {
        let mut out = String::new();
        for t in &self.tokens[start..end.min(self.tokens.len())] {
            match &t.tok {
                Tok::Name(s) | Tok::Number(_, s) => out.push_str(s),
                Tok::Sym(c) => out.push(*c),
            }
            if let Some((cut, _)) = out.char_indices().nth(QUOTED_CHARS) {
                out.truncate(cut);
                out.push('…');
                break;
            }
        }
        out
    }

    /// Signs (`-`, `+`) before a power: read in a loop (no stack), each one level of nesting
    /// ([`Self::enter`]); whether they negate. The caller leaves the levels ([`Self::leave`]):
    /// the returned count.
    fn signs(&mut self) -> Result<(bool, usize), BertiniError> {
        let mut negate = false;
        let mut levels = 0;
        loop {
            if self.peek_sym('-') {
                negate = !negate;
            } else if !self.peek_sym('+') {
                return Ok((negate, levels));
            }
            self.enter()?;
            levels += 1;
            self.pos += 1;
        }
    }

    /// One more level of nesting (a parenthesis, a sign, a `^`), refused past [`MAX_NESTING`].
    fn enter(&mut self) -> Result<(), BertiniError> {
        if self.depth == MAX_NESTING {
            return Err(err(
                self.current_line(),
                BertiniErrorKind::Nesting {
                    context: self.context.to_string(),
                },
            ));
        }
        self.depth += 1;
        Ok(())
    }

    fn leave(&mut self, levels: usize) {
        self.depth -= levels;
    }

    fn unary(&mut self) -> Result<Poly, BertiniError> {
        let start = self.pos;
        let line = self.current_line();
        let (negate, levels) = self.signs()?;
        let p = self.power()?;
        self.leave(levels);
        if negate {
            self.spend(p.len() as u128, (start, self.pos), line)?;
            Ok(-p)
        } else {
            Ok(p)
        }
    }

    /// `base ^ e1 ^ e2 …`, right-associative (`x^2^3` is `x^8`), each exponent signs and a
    /// primary: read as a list (each `^` and sign one level of nesting, [`MAX_NESTING`]) and
    /// folded from the right, without recursion. Every power but the base's is of constants.
    fn power(&mut self) -> Result<Poly, BertiniError> {
        struct Operand {
            /// Where the operand starts (after its signs).
            start: usize,
            /// The line of the `^` before it.
            line: usize,
            /// Where its exponent (the `^`'s right side, signs included) starts.
            exponent_start: usize,
            negate: bool,
            value: Poly,
        }
        let whole = self.pos;
        let base = self.primary()?;
        if !self.peek_sym('^') {
            return Ok(base);
        }
        let mut chain = Vec::new();
        let mut operand_start = whole;
        let mut levels = 0;
        while self.peek_sym('^') {
            let line = self.current_line();
            self.enter()?;
            self.pos += 1;
            let exponent_start = self.pos;
            let (negate, signs) = self.signs()?;
            levels += 1 + signs;
            let start = self.pos;
            let value = self.primary()?;
            chain.push(Operand {
                start: operand_start,
                line,
                exponent_start,
                negate,
                value,
            });
            operand_start = start;
        }
        self.leave(levels);
        let end = self.pos;
        // Fold from the right: the last operand, with its signs, is the last exponent; each
        // power found is, with the signs of the operand it raised, the exponent of the `^`
        // before. The base's own signs belong to `unary`.
        let last = chain.len() - 1;
        let mut exponent = std::mem::replace(&mut chain[last].value, Poly::zero(0));
        if chain[last].negate {
            exponent = -exponent;
        }
        let mut raised = Vec::with_capacity(chain.len());
        raised.push(base);
        for o in &mut chain[..last] {
            raised.push(std::mem::replace(&mut o.value, Poly::zero(0)));
        }
        for k in (0..chain.len()).rev() {
            let op = &chain[k];
            let base = raised.pop().expect("one raised operand per '^'");
            let value = self.raise(
                &base,
                &exponent,
                (op.start, end),
                op.exponent_start,
                op.line,
            )?;
            exponent = if k > 0 && chain[k - 1].negate {
                -value
            } else {
                value
            };
        }
        Ok(exponent)
    }

    /// `base ^ exponent`, the power written from `span.0` to `span.1`, its exponent from
    /// `exponent_start` (after the `^` on line `line`).
    fn raise(
        &self,
        base: &Poly,
        exponent: &Poly,
        span: (usize, usize),
        exponent_start: usize,
        line: usize,
    ) -> Result<Poly, BertiniError> {
        let k = constant_value(exponent).and_then(|c| {
            let integral = c.im == 0.0 && c.re >= 0.0 && c.re.fract() == 0.0 && c.re < 65536.0;
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            let k = c.re as u32;
            integral.then_some(k)
        });
        let Some(k) = k else {
            return Err(self.not_polynomial(
                line,
                format!("the power '^{}'", self.source(exponent_start, span.1)),
                "exponents must be constant non-negative integers",
            ));
        };
        self.before_expanding(
            u64::from(base.total_degree()) * u64::from(k),
            expansion::power(base, k),
            span,
            line,
        )?;
        let p = base.pow(k);
        if p.is_finite() {
            Ok(p)
        } else {
            Err(err(
                line,
                BertiniErrorKind::NotFinite {
                    found: self.source(span.0, span.1),
                    context: self.context.to_string(),
                },
            ))
        }
    }

    fn primary(&mut self) -> Result<Poly, BertiniError> {
        let n = self.nvars();
        let Some(t) = self.peek().cloned() else {
            return Err(syntax(
                self.current_line(),
                format!("{} ends where an operand is expected", self.context),
            ));
        };
        self.pos += 1;
        match t.tok {
            Tok::Number(v, _) => {
                self.spend(1, (self.pos - 1, self.pos), t.line)?;
                Ok(Poly::real(n, v))
            }
            Tok::Sym('(') => {
                self.enter()?;
                let inner = self.expression()?;
                self.leave(1);
                if !self.peek_sym(')') {
                    return Err(syntax(
                        self.current_line(),
                        format!("'(' without its ')' in {}", self.context),
                    ));
                }
                self.pos += 1;
                Ok(inner)
            }
            Tok::Sym(_) => Err(syntax(
                t.line,
                format!("unexpected {} in {}", t.describe(), self.context),
            )),
            Tok::Name(name) => {
                if self.peek_sym('(') {
                    let why = if TRANSCENDENTAL.contains(&name.as_str()) {
                        "kinsyn reads polynomial systems only"
                    } else {
                        "Bertini has no such function, and kinsyn reads polynomials only"
                    };
                    return Err(self.not_polynomial(t.line, format!("'{name}(…)'"), why));
                }
                self.name_value(&name, t.line)
            }
        }
    }

    /// The value of a name, its terms spent (a subfunction is copied where it is used).
    fn name_value(&self, name: &str, line: usize) -> Result<Poly, BertiniError> {
        let n = self.nvars();
        let here = (self.pos - 1, self.pos);
        match name {
            "I" => {
                self.spend(1, here, line)?;
                return Ok(Poly::constant(n, C64::new(0.0, 1.0)));
            }
            "Pi" => {
                self.spend(1, here, line)?;
                return Ok(Poly::real(n, std::f64::consts::PI));
            }
            _ => {}
        }
        let unknown = || {
            err(
                line,
                BertiniErrorKind::UnknownName {
                    name: name.to_string(),
                    context: self.context.to_string(),
                },
            )
        };
        let copy = |p: &Poly| -> Result<Poly, BertiniError> {
            self.spend(p.len() as u128, here, line)?;
            Ok(p.clone())
        };
        match self.reader.names.get(name) {
            Some(Name::Variable(i)) => {
                self.spend(1, here, line)?;
                Ok(Poly::variable(n, *i))
            }
            Some(Name::Subfunction(p)) => copy(p),
            Some(Name::Function(k)) => match &self.reader.functions[*k].2 {
                Some(p) => copy(p),
                None => Err(unknown()),
            },
            Some(Name::Constant(k)) => match self.reader.constants[*k].2 {
                Some(c) => {
                    self.spend(1, here, line)?;
                    Ok(Poly::constant(n, c))
                }
                None => Err(err(
                    line,
                    BertiniErrorKind::Declaration(format!(
                        "constant '{name}' is used in {} before it is assigned",
                        self.context
                    )),
                )),
            },
            None => Err(unknown()),
        }
    }
}

/// `p / c` for a non-zero constant `c`: real divisors divide each coefficient (exactly as
/// written, so `x/4` is `0.25*x`), complex ones multiply by the reciprocal.
fn divide(p: &Poly, c: C64) -> Poly {
    if c.im == 0.0 {
        Poly::from_terms(
            p.nvars(),
            p.terms()
                .map(|(e, a)| (e.to_vec(), C64::new(a.re / c.re, a.im / c.re))),
        )
    } else {
        p.scale(C64::new(1.0, 0.0) / c)
    }
}

// ---------------------------------------------------------------------------------------
// Writing

/// `p` written with the given names, coefficients exactly (shortest round-trip decimals),
/// complex ones as `(a + b*U)` with `U` the solver's imaginary unit.
pub(crate) fn format_poly(p: &Poly, names: &[String], unit: &str) -> String {
    if p.is_empty() {
        return "0".into();
    }
    let mut out = String::new();
    let terms: Vec<(&[u32], C64)> = p.terms().collect();
    for (k, (e, c)) in terms.iter().rev().enumerate() {
        let monomial: Vec<String> = e
            .iter()
            .enumerate()
            .filter(|(_, k)| **k > 0)
            .map(|(i, k)| {
                if *k == 1 {
                    names[i].clone()
                } else {
                    format!("{}^{k}", names[i])
                }
            })
            .collect();
        let (negative, coefficient) = if c.im == 0.0 {
            let magnitude = c.re.abs();
            #[allow(clippy::float_cmp)] // the exact coefficient 1 is left implicit
            let text = if magnitude == 1.0 && !monomial.is_empty() {
                String::new()
            } else {
                format!("{magnitude:?}")
            };
            (c.re.is_sign_negative(), text)
        } else {
            let sign = if c.im.is_sign_negative() { '-' } else { '+' };
            (
                false,
                format!("({:?} {sign} {:?}*{unit})", c.re, c.im.abs()),
            )
        };
        match (k, negative) {
            (0, true) => out.push('-'),
            (0, false) => {}
            (_, true) => out.push_str(" - "),
            (_, false) => out.push_str(" + "),
        }
        out.push_str(&coefficient);
        if !coefficient.is_empty() && !monomial.is_empty() {
            out.push('*');
        }
        out.push_str(&monomial.join("*"));
    }
    out
}

/// Names for the variables that are valid in a Bertini file: each name kept when it is a
/// Bertini identifier ([`is_valid_name`]), otherwise replaced by `v{k}` (`k` its 1-based
/// index, with primes `_` appended until unused).
pub(crate) fn safe_names(
    names: &[String],
    valid: impl Fn(&str) -> bool,
    prefix: &str,
) -> Vec<String> {
    let mut out: Vec<String> = names
        .iter()
        .map(|n| if valid(n) { n.clone() } else { String::new() })
        .collect();
    for k in 0..out.len() {
        if out[k].is_empty() {
            let mut candidate = format!("{prefix}{}", k + 1);
            while out.contains(&candidate) || names.contains(&candidate) {
                candidate.push('_');
            }
            out[k] = candidate;
        }
    }
    out
}

/// A Bertini input file for `system`: one `variable_group` line per variable group, the
/// equations as functions `f1, f2, …` with every coefficient written exactly, so that
/// [`parse`] reads back the same system (same variables, groups and coefficients). Variable
/// names that are not Bertini identifiers ([`is_valid_name`]) are written as `v1, v2, …`
/// (a comment lists the original names); only then does the round trip change the names.
///
/// Non-finite coefficients (infinities, NaN) have no Bertini spelling: they are written as
/// Rust prints them, and [`parse`] refuses them.
#[must_use]
pub fn write(system: &System) -> String {
    let names = safe_names(system.variables(), is_valid_name, "v");
    let mut out = String::from("% written by kinsyn\n");
    for (k, (new, old)) in names.iter().zip(system.variables()).enumerate() {
        if new != old {
            let _ = writeln!(out, "% variable {} ({new}) is {old:?}", k + 1);
        }
    }
    out.push_str("INPUT\n");
    for g in system.groups() {
        let list: Vec<&str> = g.iter().map(|i| names[*i].as_str()).collect();
        let _ = writeln!(out, "  variable_group {};", list.join(", "));
    }
    let functions = function_names(&names, system.len());
    if !functions.is_empty() {
        let _ = writeln!(out, "  function {};", functions.join(", "));
    }
    for (f, p) in functions.iter().zip(system.equations()) {
        let _ = writeln!(out, "  {f} = {};", format_poly(p, &names, "I"));
    }
    out.push_str("END;\n");
    out
}

/// `f1, f2, …`, each renamed (`_` appended) if a variable has that name.
fn function_names(variables: &[String], count: usize) -> Vec<String> {
    (1..=count)
        .map(|k| {
            let mut name = format!("f{k}");
            while variables.contains(&name) {
                name.push('_');
            }
            name
        })
        .collect()
}
