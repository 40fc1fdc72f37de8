//! What the facade's error types share: the one unknown-name error
//! ([`UnknownName`]) and the macro that writes each error enum's `Display`,
//! `Error` and `From` impls once.

use std::fmt;

/// What a name was meant to name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum NameKind {
    /// A point of the model (or a ground point).
    Point,
    /// A coordinate of the model, in u or v.
    Coordinate,
    /// A body of a force analysis.
    Body,
    /// A parameter of the model (`params = [...]`).
    Parameter,
}

impl fmt::Display for NameKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            NameKind::Point => "point",
            NameKind::Coordinate => "coordinate",
            NameKind::Body => "body",
            NameKind::Parameter => "parameter",
        })
    }
}

/// A description names something that is not there: `owner` (a body, a
/// load, a joint, the scene) names the `kind` `name`, which is not among
/// `known` (the names it could have meant, comma-separated).
#[derive(Clone, Debug, PartialEq)]
pub struct UnknownName {
    pub kind: NameKind,
    pub owner: String,
    pub name: String,
    pub known: String,
}

impl UnknownName {
    pub(crate) fn new<'a>(
        kind: NameKind,
        owner: &str,
        name: &str,
        known: impl IntoIterator<Item = &'a str>,
    ) -> UnknownName {
        UnknownName {
            kind,
            owner: owner.into(),
            name: name.into(),
            known: known.into_iter().collect::<Vec<_>>().join(", "),
        }
    }
}

impl fmt::Display for UnknownName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let UnknownName {
            kind,
            owner,
            name,
            known,
        } = self;
        write!(
            f,
            "`{owner}` names the {kind} `{name}`, which is not defined (the {kind}s: {known})"
        )
    }
}

impl std::error::Error for UnknownName {}

/// `Display` (one format per variant), `std::error::Error` (with the
/// wrapped errors as sources) and `From` for each wrapped error, of an
/// error enum:
///
/// ```text
/// error_impls! {
///     MachineError {
///         Self::Stalls { phi } => ("the machine stalls at φ = {phi}"),
///         Self::Kinematics(inner) => ("kinematics: {inner}"),
///     }
///     wraps { Kinematics(crate::runtime::Error) }
/// }
/// ```
///
/// An enum that can meet an unknown name wraps [`UnknownName`] like any
/// other error: `UnknownName(UnknownName)`, displayed as `("{inner}")`.
/// An optional `sources { Variant(Inner) }` after `wraps` gives such a
/// variant its source but no `From`: where an inner error means one thing
/// only (the options of a search), `?` must not label every other one so.
/// An optional `field_sources { Variant.field }` after that gives a struct
/// variant its field as its source (no `From`: the other fields need
/// values).
macro_rules! error_impls {
    (
        $error:ident {
            $($pattern:pat => ($($format:tt)+),)*
        }
        wraps { $($variant:ident($inner:ty)),* $(,)? }
        $(sources { $($source:ident($source_inner:ty)),* $(,)? })?
        $(field_sources { $($field_variant:ident.$field:ident),* $(,)? })?
    ) => {
        impl std::fmt::Display for $error {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                match self {
                    $($pattern => write!(f, $($format)+),)*
                }
            }
        }

        impl std::error::Error for $error {
            fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
                match self {
                    $(Self::$variant(inner) => Some(inner),)*
                    $($(Self::$source(inner) => Some(inner),)*)?
                    $($(Self::$field_variant { $field, .. } => Some($field),)*)?
                    #[allow(unreachable_patterns)]
                    _ => None,
                }
            }
        }

        $(impl From<$inner> for $error {
            fn from(e: $inner) -> Self {
                Self::$variant(e)
            }
        })*
    };
}

pub(crate) use error_impls;
