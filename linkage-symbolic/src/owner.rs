//! Who the equations and their parameters belong to, worded for messages:
//! a struct under `#[linkage::linkage(...)]`, whose parameters are its
//! `f64` fields, or a mechanism given as text at run time, whose
//! parameters are named beside its equations. Every message that names
//! the parameters' owner or the equations' container takes its words from
//! here, so that the two paths share one set of messages (the attribute's
//! read exactly as they always have).

/// The owner of the parameters, with its name as written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Owner {
    /// The struct under the attribute: its parameters are its `f64` fields.
    Struct(String),
    /// A mechanism read at run time: its parameters are declared with it.
    Mechanism(String),
}

impl Owner {
    /// The owner's name as written (`FourBar`).
    pub fn name(&self) -> &str {
        match self {
            Owner::Struct(name) | Owner::Mechanism(name) => name,
        }
    }

    /// What belongs to the owner, whatever its use: "a field of
    /// `FourBar`" / "a parameter of `FourBar`".
    pub fn a_member(&self) -> String {
        match self {
            Owner::Struct(name) => format!("a field of `{name}`"),
            Owner::Mechanism(name) => format!("a parameter of `{name}`"),
        }
    }

    /// One of the parameters an equation can use: "an `f64` field of
    /// `FourBar`" / "a parameter of `FourBar`".
    pub fn a_parameter(&self) -> String {
        match self {
            Owner::Struct(name) => format!("an `f64` field of `{name}`"),
            Owner::Mechanism(name) => format!("a parameter of `{name}`"),
        }
    }

    /// The same, the owner unnamed: "an `f64` field of the struct" / "a
    /// parameter of the mechanism".
    pub fn a_parameter_of_it(&self) -> &'static str {
        match self {
            Owner::Struct(_) => "an `f64` field of the struct",
            Owner::Mechanism(_) => "a parameter of the mechanism",
        }
    }

    /// The parameters, owner named: "`f64` fields of `FourBar`" /
    /// "parameters of `FourBar`".
    pub fn parameters(&self) -> String {
        format!("{} of `{}`", self.parameters_kind(), self.name())
    }

    /// The kind of the parameters, plural: "`f64` fields" / "parameters".
    pub fn parameters_kind(&self) -> &'static str {
        match self {
            Owner::Struct(_) => "`f64` fields",
            Owner::Mechanism(_) => "parameters",
        }
    }

    /// The kind of a parameter: "`f64` field" / "parameter".
    pub fn parameter_kind(&self) -> &'static str {
        match self {
            Owner::Struct(_) => "`f64` field",
            Owner::Mechanism(_) => "parameter",
        }
    }

    /// All the parameters, owner unnamed: "the struct's `f64` fields" /
    /// "the mechanism's parameters".
    pub fn its_parameters(&self) -> &'static str {
        match self {
            Owner::Struct(_) => "the struct's `f64` fields",
            Owner::Mechanism(_) => "the mechanism's parameters",
        }
    }

    /// Where the equations are written, as a place: "#[linkage::linkage(...)]"
    /// / "the mechanism `FourBar`".
    pub fn where_written(&self) -> String {
        match self {
            Owner::Struct(_) => "#[linkage::linkage(...)]".to_owned(),
            Owner::Mechanism(name) => format!("the mechanism `{name}`"),
        }
    }

    /// What reads the equations, as the subject of a sentence: "the
    /// attribute" / "a mechanism".
    pub fn reader(&self) -> &'static str {
        match self {
            Owner::Struct(_) => "the attribute",
            Owner::Mechanism(_) => "a mechanism",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Owner;

    /// The attribute's words, as its messages have always read.
    #[test]
    fn the_struct_is_worded_as_before() {
        let owner = Owner::Struct("FourBar".to_owned());
        assert_eq!(owner.a_member(), "a field of `FourBar`");
        assert_eq!(owner.a_parameter(), "an `f64` field of `FourBar`");
        assert_eq!(owner.parameters(), "`f64` fields of `FourBar`");
        assert_eq!(owner.where_written(), "#[linkage::linkage(...)]");
    }

    #[test]
    fn a_mechanism_has_parameters() {
        let owner = Owner::Mechanism("FourBar".to_owned());
        assert_eq!(owner.a_member(), "a parameter of `FourBar`");
        assert_eq!(owner.a_parameter(), "a parameter of `FourBar`");
        assert_eq!(owner.parameters(), "parameters of `FourBar`");
        assert_eq!(owner.where_written(), "the mechanism `FourBar`");
    }
}
