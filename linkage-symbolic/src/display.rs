//! Formulas as text, for the doc comments of the generated functions and the
//! symbolic table: `-l3·sin θ3`, `l2·cos θ2 + l3·cos θ3 + l4·cos θ4 - l1`.

use crate::dag::{Dag, Func, Func2, Id, Node, Symbol};
use crate::names::SymbolNames;

/// Binding strength, for parentheses.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Prec {
    Sum,
    Product,
    Atom,
}

/// Renders formulas of one DAG.
pub struct Formatter<'a> {
    pub dag: &'a Dag,
    pub names: &'a SymbolNames,
}

impl Formatter<'_> {
    /// The formula of a node.
    pub fn format(&self, id: Id) -> String {
        self.render(id).0
    }

    fn wrap(&self, id: Id, at_least: Prec) -> String {
        let (s, p) = self.render(id);
        if p < at_least { format!("({s})") } else { s }
    }

    fn render(&self, id: Id) -> (String, Prec) {
        match self.dag.node(id) {
            Node::Const(c) => {
                let c = c.get();
                (number(c), if c < 0.0 { Prec::Sum } else { Prec::Atom })
            }
            Node::Sym(s) => {
                let text = self.names.display(*s);
                let compound = matches!(s, Symbol::Constant(_)) && text.contains(['/', ' ']);
                (text, if compound { Prec::Product } else { Prec::Atom })
            }
            Node::Sum(terms) if terms.len() > 1 => {
                if let Some(factored) = self.factored(terms) {
                    return (factored, Prec::Product);
                }
                let ordered =
                    display_order(self.dag, terms.iter().map(|&(c, t)| (c.get(), t)).collect());
                let mut out = String::new();
                for (k, (c, t)) in ordered.into_iter().enumerate() {
                    let negative = c < 0.0;
                    let body = if t == Dag::ONE {
                        number(c.abs())
                    } else {
                        self.scaled(c.abs(), t)
                    };
                    match (k, negative) {
                        (0, false) => out.push_str(&body),
                        (0, true) => {
                            out.push('-');
                            out.push_str(&body);
                        }
                        (_, false) => {
                            out.push_str(" + ");
                            out.push_str(&body);
                        }
                        (_, true) => {
                            out.push_str(" - ");
                            out.push_str(&body);
                        }
                    }
                }
                (out, Prec::Sum)
            }
            Node::Sum(terms) => {
                let (c, t) = (terms[0].0.get(), terms[0].1);
                let body = self.scaled(c.abs(), t);
                if c < 0.0 {
                    (format!("-{body}"), Prec::Sum)
                } else {
                    (body, Prec::Product)
                }
            }
            Node::Prod(factors) => (self.product(1.0, factors), Prec::Product),
            Node::Call(f, a) => (self.call(*f, *a), Prec::Atom),
            Node::Call2(f, a, b) => {
                let s = match f {
                    Func2::Atan2 => format!("atan2({}, {})", self.format(*a), self.format(*b)),
                    Func2::Hypot => format!("hypot({}, {})", self.format(*a), self.format(*b)),
                    Func2::Powf => format!(
                        "{}^{}",
                        self.wrap(*a, Prec::Atom),
                        self.wrap(*b, Prec::Atom)
                    ),
                };
                (s, Prec::Atom)
            }
        }
    }

    /// The factors of a term with positive exponents.
    fn positive_factors(&self, t: Id) -> Vec<(Id, i32)> {
        match self.dag.node(t) {
            Node::Prod(factors) => factors.iter().copied().filter(|f| f.1 > 0).collect(),
            _ => vec![(t, 1)],
        }
    }

    /// A sum whose terms share factors, shown with them pulled out:
    /// `-l3·l4·(sin θ3·cos θ4 - cos θ3·sin θ4)`. Display only: the DAG and the
    /// emitted code keep the expanded form.
    fn factored(&self, terms: &[(crate::dag::Num, Id)]) -> Option<String> {
        if terms.iter().any(|&(_, t)| t == Dag::ONE) {
            return None;
        }
        let mut common = self.positive_factors(terms[0].1);
        for &(_, t) in &terms[1..] {
            let factors = self.positive_factors(t);
            common.retain_mut(|(id, e)| match factors.iter().find(|f| f.0 == *id) {
                Some(&(_, e2)) => {
                    *e = (*e).min(e2);
                    true
                }
                None => false,
            });
        }
        if common.is_empty() {
            return None;
        }
        let ordered = display_order(self.dag, terms.iter().map(|&(c, t)| (c.get(), t)).collect());
        let magnitudes: Vec<f64> = ordered.iter().map(|(c, _)| c.abs()).collect();
        let shared = if magnitudes.iter().all(|&m| m == magnitudes[0]) {
            magnitudes[0]
        } else {
            1.0
        };
        let sign = if ordered[0].0 < 0.0 { -1.0 } else { 1.0 };
        let mut inner = String::new();
        for (k, &(c, t)) in ordered.iter().enumerate() {
            let factors: Vec<(Id, i32)> = match self.dag.node(t) {
                Node::Prod(f) => f.clone(),
                _ => vec![(t, 1)],
            };
            let rest: Vec<(Id, i32)> = factors
                .into_iter()
                .filter_map(|(id, e)| {
                    let e = e - common.iter().find(|f| f.0 == id).map_or(0, |f| f.1);
                    (e != 0).then_some((id, e))
                })
                .collect();
            let c = c * sign / shared;
            let body = if rest.is_empty() {
                number(c.abs())
            } else if rest.len() == 1 && rest[0].1 == 1 {
                self.scaled(c.abs(), rest[0].0)
            } else {
                self.product(c.abs(), &rest)
            };
            match (k, c < 0.0) {
                (0, false) => inner.push_str(&body),
                (0, true) => inner.push_str(&format!("-{body}")),
                (_, false) => inner.push_str(&format!(" + {body}")),
                (_, true) => inner.push_str(&format!(" - {body}")),
            }
        }
        let outer = self.product(shared, &common);
        let sign = if sign < 0.0 { "-" } else { "" };
        Some(format!("{sign}{outer}·({inner})"))
    }

    /// `c·t` for `c > 0`, with the coefficient merged into a product.
    fn scaled(&self, c: f64, t: Id) -> String {
        match self.dag.node(t) {
            Node::Prod(factors) => self.product(c, factors),
            _ if c == 1.0 => self.wrap(t, Prec::Product),
            _ => format!("{}·{}", number(c), self.wrap(t, Prec::Product)),
        }
    }

    /// `c·Π fᵢ^eᵢ` as `c·a·b/(d·e²)`.
    fn product(&self, c: f64, factors: &[(Id, i32)]) -> String {
        let mut numerator: Vec<String> = Vec::new();
        if c != 1.0 {
            numerator.push(number(c));
        }
        let mut denominator: Vec<String> = Vec::new();
        for (f, e) in factor_order(self.dag, factors) {
            let text = self.power(f, e.unsigned_abs());
            if e > 0 {
                numerator.push(text);
            } else {
                denominator.push(text);
            }
        }
        let num = if numerator.is_empty() {
            "1".to_owned()
        } else {
            numerator.join("·")
        };
        match denominator.len() {
            0 => num,
            1 => format!("{num}/{}", denominator[0]),
            _ => format!("{num}/({})", denominator.join("·")),
        }
    }

    /// `f^e` with a superscript exponent.
    fn power(&self, f: Id, e: u32) -> String {
        if e == 1 {
            return self.wrap(f, Prec::Atom);
        }
        let base = match self.dag.node(f) {
            // sin(θ3)² rather than sin θ3²
            Node::Call(func, a) if !matches!(func, Func::Abs | Func::Sqrt) => {
                format!("{}({})", func_name(*func), self.format(*a))
            }
            _ => self.wrap(f, Prec::Atom),
        };
        format!("{base}{}", superscript(e))
    }

    fn call(&self, f: Func, a: Id) -> String {
        let simple = matches!(self.dag.node(a), Node::Sym(_));
        match f {
            Func::Abs => format!("|{}|", self.format(a)),
            Func::Sqrt => format!("√{}", self.wrap(a, Prec::Atom)),
            _ if simple => format!("{} {}", func_name(f), self.format(a)),
            _ => format!("{}({})", func_name(f), self.format(a)),
        }
    }
}

fn func_name(f: Func) -> &'static str {
    match f {
        Func::Signum => "sgn",
        other => other.method(),
    }
}

/// Factors in reading order: parameters and constants, then coordinates,
/// then functions and other expressions, then velocities, then
/// accelerations (`l3·l4·sin θ3·cos θ4`, `l3·cos θ3·θ̇3²`).
pub fn factor_order(dag: &Dag, factors: &[(Id, i32)]) -> Vec<(Id, i32)> {
    let rank = |id: Id| match dag.node(id) {
        Node::Sym(Symbol::Param(_) | Symbol::Constant(_)) => 0,
        Node::Sym(Symbol::Coord(_)) => 1,
        Node::Sym(Symbol::Vel(_)) => 3,
        Node::Sym(Symbol::Acc(_)) => 4,
        _ => 2,
    };
    let mut out = factors.to_vec();
    out.sort_by_key(|&(id, _)| (rank(id), id));
    out
}

/// Terms in reading order: as created (the order of the source), with the
/// constant term last.
pub fn display_order(dag: &Dag, mut terms: Vec<(f64, Id)>) -> Vec<(f64, Id)> {
    terms.sort_by_key(|&(_, t)| (t == Dag::ONE || dag.as_const(t).is_some(), t));
    terms
}

/// The shortest text that reads back as the same `f64` (`2`, `0.5`, `1e-9`).
pub fn number(c: f64) -> String {
    let s = format!("{c}");
    if s.len() > 8 {
        let e = format!("{c:e}");
        if e.len() < s.len() {
            return e;
        }
    }
    s
}

fn superscript(n: u32) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    n.to_string()
        .chars()
        .map(|d| DIGITS[d.to_digit(10).unwrap_or(0) as usize])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn common_factors_are_pulled_out_for_display() {
        let mut dag = Dag::new();
        let l3 = dag.sym(Symbol::Param(0));
        let l4 = dag.sym(Symbol::Param(1));
        let t3 = dag.sym(Symbol::Coord(0));
        let t4 = dag.sym(Symbol::Coord(1));
        let (s3, c3) = (dag.call(Func::Sin, t3), dag.call(Func::Cos, t3));
        let (s4, c4) = (dag.call(Func::Sin, t4), dag.call(Func::Cos, t4));
        let a = dag.product([(l3, 1), (l4, 1), (s3, 1), (c4, 1)]);
        let b = dag.product([(l3, 1), (l4, 1), (c3, 1), (s4, 1)]);
        let det = dag.sum([(-1.0, a), (1.0, b)]);
        let names = SymbolNames::new(
            vec!["l3".into(), "l4".into()],
            vec!["theta3".into(), "theta4".into()],
            2,
            vec![0, 1],
        );
        let f = Formatter {
            dag: &dag,
            names: &names,
        };
        assert_eq!(f.format(det), "-l3·l4·(sin θ3·cos θ4 - cos θ3·sin θ4)");
    }

    #[test]
    fn numbers() {
        assert_eq!(number(2.0), "2");
        assert_eq!(number(0.5), "0.5");
        assert_eq!(number(1e-9), "1e-9");
    }
}
