//! kinsyn's failures as Python exceptions: `KinsynError`, and `InputError` for bad input (what
//! the command line refuses with exit code 2), each with the command's one-line message.

use pyo3::PyErr;
use pyo3::create_exception;
use pyo3::exceptions::PyException;

create_exception!(
    kinsyn,
    KinsynError,
    PyException,
    "A kinsyn failure; str() is the one-line message the kinsyn command prints after `kinsyn: error: `."
);
create_exception!(
    kinsyn,
    InputError,
    KinsynError,
    "Bad input (a missing or malformed file, chain, pattern, pose, input value or option): what the kinsyn command refuses with exit code 2."
);

pub use kinsyn_report::Error;

/// `e` as a Python exception: bad input as [`InputError`], anything else as [`KinsynError`],
/// with the command's one-line message.
#[expect(
    clippy::needless_pass_by_value,
    reason = "used as `map_err(py_err)`, which passes the error by value"
)]
pub fn py_err(e: Error) -> PyErr {
    let message = kinsyn_report::terminal::one_line(&e.to_string());
    match e {
        Error::Input(_) => InputError::new_err(message),
        Error::Io(_) | Error::Internal(_) => KinsynError::new_err(message),
    }
}
