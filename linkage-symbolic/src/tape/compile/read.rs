//! Reading the emitted statements: the `let` bindings, tuples, indexing,
//! arithmetic, unary minus, parentheses, literals, the constants of
//! `core::f64::consts` and the `f64` methods the emitter writes, with
//! Rust's precedence and associativity, into operations in the order Rust
//! evaluates them. It reads the tokens as rustc does — what compiles is
//! what runs — and nothing but the forms the emitter writes: anything else
//! is an error, never a guess.

use super::CompileError;
use super::builder::{Builder, Val};
use crate::dag::Constant;
use crate::hasher::FastMap;
use crate::tape::op::Code;
use crate::tape::slots::Input;
use proc_macro2::{Delimiter, Group, Ident, Literal, TokenStream, TokenTree};

/// A value of the emitted code.
#[derive(Clone, Debug)]
enum Value {
    Num(Val),
    Tuple(Vec<Value>),
    /// An argument vector, by the registers of its entries.
    Array(Input),
}

/// A `let` pattern.
enum Pattern {
    Name(String),
    Tuple(Vec<Pattern>),
    /// `Self { a, b, .. }`.
    Fields(Vec<String>),
}

/// The reader: the values bound so far and the program they build.
pub(super) struct Reader<'b> {
    builder: &'b mut Builder,
    /// The bindings of the statements read so far.
    env: FastMap<String, Value>,
    /// The argument vectors by name.
    arrays: FastMap<String, Input>,
    /// The struct's `f64` fields by name: their registers.
    fields: FastMap<String, u32>,
    /// Where each input's registers start.
    starts: FastMap<Input, (u32, usize)>,
}

type Result<T> = std::result::Result<T, CompileError>;

fn error<T>(what: impl std::fmt::Display) -> Result<T> {
    Err(CompileError::new(what.to_string()))
}

impl<'b> Reader<'b> {
    /// A reader whose arrays are the inputs (`trig` the names of the
    /// sine-and-cosine arrays), whose fields are read from `Self`, and in
    /// which the `late` names (bound by the caller between phases) already
    /// stand for their registers.
    pub(super) fn new(
        builder: &'b mut Builder,
        inputs: impl IntoIterator<Item = (Input, u32, usize)>,
        trig: [String; 2],
        fields: impl IntoIterator<Item = (String, u32)>,
        late: impl IntoIterator<Item = (String, u32)>,
    ) -> Reader<'b> {
        let [trig_u, trig_v] = trig;
        let arrays = [
            ("u".to_owned(), Input::U),
            ("v".to_owned(), Input::V),
            ("udot".to_owned(), Input::Udot),
            ("vdot".to_owned(), Input::Vdot),
            ("uddot".to_owned(), Input::Uddot),
            ("vddot".to_owned(), Input::Vddot),
            (trig_u, Input::TrigU),
            (trig_v, Input::TrigV),
        ]
        .into_iter()
        .collect();
        let env = late
            .into_iter()
            .map(|(name, r)| (name, Value::Num(Val::Reg(r))))
            .collect();
        Reader {
            builder,
            env,
            arrays,
            fields: fields.into_iter().collect(),
            starts: inputs
                .into_iter()
                .map(|(input, start, len)| (input, (start, len)))
                .collect(),
        }
    }

    /// One `let` statement.
    pub(super) fn statement(&mut self, statement: &TokenStream) -> Result<()> {
        let tokens: Vec<TokenTree> = statement.clone().into_iter().collect();
        let mut c = Cursor::new(&tokens);
        c.keyword("let")?;
        let pattern = pattern(&mut c)?;
        c.punct('=')?;
        if let Pattern::Fields(names) = pattern {
            c.punct('*')?;
            c.keyword("self")?;
            c.punct(';')?;
            c.end()?;
            for name in names {
                let Some(&r) = self.fields.get(&name) else {
                    return error(format_args!("`{name}` is not an f64 field"));
                };
                self.env.insert(name, Value::Num(Val::Reg(r)));
            }
            return Ok(());
        }
        let value = self.expr(&mut c)?;
        c.punct(';')?;
        c.end()?;
        self.bind(pattern, value)
    }

    /// Ends a phase whose outputs are these expressions.
    pub(super) fn end_phase(&mut self, outputs: &[TokenStream]) -> Result<()> {
        let mut values = Vec::with_capacity(outputs.len());
        for expression in outputs {
            let tokens: Vec<TokenTree> = expression.clone().into_iter().collect();
            let mut c = Cursor::new(&tokens);
            let value = self.expr(&mut c)?;
            c.end()?;
            values.push(number(value)?);
        }
        self.builder.end_phase(values);
        Ok(())
    }

    /// The value of an expression (a test's look at what was read).
    #[cfg(test)]
    fn value(&mut self, expression: &str) -> Result<Val> {
        let tokens: Vec<TokenTree> = expression
            .parse::<TokenStream>()
            .map_err(|e| CompileError::new(e.to_string()))?
            .into_iter()
            .collect();
        let mut c = Cursor::new(&tokens);
        let value = self.expr(&mut c)?;
        c.end()?;
        number(value)
    }

    fn bind(&mut self, pattern: Pattern, value: Value) -> Result<()> {
        match (pattern, value) {
            (Pattern::Name(name), value) => {
                self.env.insert(name, value);
                Ok(())
            }
            (Pattern::Tuple(patterns), Value::Tuple(values)) if patterns.len() == values.len() => {
                for (p, v) in patterns.into_iter().zip(values) {
                    self.bind(p, v)?;
                }
                Ok(())
            }
            (_, value) => error(format_args!("cannot bind {value:?} to a pattern")),
        }
    }

    /// `a + b - c …`, left to right.
    fn expr(&mut self, c: &mut Cursor) -> Result<Value> {
        let mut left = self.product(c)?;
        while let Some(op) = c.peek_punct(&['+', '-']) {
            c.advance();
            let right = self.product(c)?;
            let code = if op == '+' { Code::Add } else { Code::Sub };
            left = Value::Num(self.builder.op(code, number(left)?, number(right)?));
        }
        Ok(left)
    }

    /// `a * b / c …`, left to right.
    fn product(&mut self, c: &mut Cursor) -> Result<Value> {
        let mut left = self.unary(c)?;
        while let Some(op) = c.peek_punct(&['*', '/']) {
            c.advance();
            let right = self.unary(c)?;
            let code = if op == '*' { Code::Mul } else { Code::Div };
            left = Value::Num(self.builder.op(code, number(left)?, number(right)?));
        }
        Ok(left)
    }

    /// `-x`, binding less tightly than a method call (`-x.powi(2)` is
    /// `-(x.powi(2))`) and more than `*`.
    fn unary(&mut self, c: &mut Cursor) -> Result<Value> {
        if c.peek_punct(&['-']).is_some() {
            c.advance();
            let operand = self.unary(c)?;
            return Ok(Value::Num(self.builder.unary(Code::Neg, number(operand)?)));
        }
        self.postfix(c)
    }

    /// A primary followed by method calls, tuple fields and indices.
    fn postfix(&mut self, c: &mut Cursor) -> Result<Value> {
        let mut value = self.primary(c)?;
        loop {
            if c.peek_punct(&['.']).is_some() {
                c.advance();
                match c.next() {
                    Some(TokenTree::Ident(method)) => {
                        let Some(TokenTree::Group(args)) = c.next() else {
                            return error(format_args!("`.{method}` without arguments"));
                        };
                        value = self.method(value, method, args)?;
                    }
                    Some(TokenTree::Literal(field)) => {
                        let k = index(field)?;
                        value = match value {
                            Value::Tuple(mut items) if k < items.len() => items.swap_remove(k),
                            other => return error(format_args!("field {k} of {other:?}")),
                        };
                    }
                    other => return error(format_args!("`.` followed by {other:?}")),
                }
            } else if let Some(TokenTree::Group(g)) = c.peek() {
                if g.delimiter() != Delimiter::Bracket {
                    break;
                }
                c.advance();
                let tokens: Vec<TokenTree> = g.stream().into_iter().collect();
                let k = match tokens.as_slice() {
                    [TokenTree::Literal(l)] => index(l)?,
                    _ => return error(format_args!("the index [{}]", g.stream())),
                };
                value = self.index(value, k)?;
            } else {
                break;
            }
        }
        Ok(value)
    }

    /// Entry k of an argument vector; of `trig_u`, the pair (sin, cos).
    fn index(&mut self, value: Value, k: usize) -> Result<Value> {
        let Value::Array(input) = value else {
            return error(format_args!("indexing {value:?}"));
        };
        let Some(&(start, len)) = self.starts.get(&input) else {
            return error(format_args!("the input {input:?}"));
        };
        let register = |i: usize| Value::Num(Val::Reg(start + i as u32));
        match input {
            Input::TrigU | Input::TrigV if 2 * k + 1 < len => {
                Ok(Value::Tuple(vec![register(2 * k), register(2 * k + 1)]))
            }
            Input::TrigU | Input::TrigV => error(format_args!("{input:?}[{k}]")),
            _ if k < len => Ok(register(k)),
            _ => error(format_args!("{input:?}[{k}] past its {len} entries")),
        }
    }

    fn primary(&mut self, c: &mut Cursor) -> Result<Value> {
        match c.next() {
            Some(TokenTree::Literal(l)) => Ok(Value::Num(Val::Const(float(l)?))),
            Some(TokenTree::Ident(name)) => {
                let name = name.to_string();
                if let Some(value) = self.env.get(&name) {
                    return Ok(value.clone());
                }
                match self.arrays.get(&name) {
                    Some(&input) => Ok(Value::Array(input)),
                    None => error(format_args!("the name `{name}` is not bound")),
                }
            }
            // `::core::f64::consts::PI`
            Some(TokenTree::Punct(p)) if p.as_char() == ':' => {
                c.punct(':')?;
                let last = loop {
                    let segment = match c.next() {
                        Some(TokenTree::Ident(segment)) => segment.to_string(),
                        other => return error(format_args!("a path segment {other:?}")),
                    };
                    if c.peek_punct(&[':']).is_none() {
                        break segment;
                    }
                    c.punct(':')?;
                    c.punct(':')?;
                };
                match Constant::from_name(&last) {
                    Some(constant) => Ok(Value::Num(Val::Const(constant.value()))),
                    None => error(format_args!("the path ending `{last}`")),
                }
            }
            Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Parenthesis => {
                let items = split_commas(g);
                if items.len() == 1 && !ends_with_comma(g) {
                    let mut inner = Cursor::new(&items[0]);
                    let value = self.expr(&mut inner)?;
                    inner.end()?;
                    return Ok(value);
                }
                let mut values = Vec::with_capacity(items.len());
                for item in &items {
                    let mut inner = Cursor::new(item);
                    values.push(self.expr(&mut inner)?);
                    inner.end()?;
                }
                Ok(Value::Tuple(values))
            }
            other => error(format_args!("the expression starting with {other:?}")),
        }
    }

    /// `receiver.method(args)`: the `f64` methods the emitter writes.
    fn method(&mut self, receiver: Value, method: &Ident, args: &Group) -> Result<Value> {
        let x = number(receiver)?;
        let mut values = Vec::new();
        for item in split_commas(args) {
            let mut inner = Cursor::new(&item);
            values.push(self.expr(&mut inner)?);
            inner.end()?;
        }
        let name = method.to_string();
        let unary = match name.as_str() {
            "sin" => Some(Code::Sin),
            "cos" => Some(Code::Cos),
            "tan" => Some(Code::Tan),
            "asin" => Some(Code::Asin),
            "acos" => Some(Code::Acos),
            "atan" => Some(Code::Atan),
            "sinh" => Some(Code::Sinh),
            "cosh" => Some(Code::Cosh),
            "tanh" => Some(Code::Tanh),
            "sqrt" => Some(Code::Sqrt),
            "exp" => Some(Code::Exp),
            "exp2" => Some(Code::Exp2),
            "ln" => Some(Code::Ln),
            "abs" => Some(Code::Abs),
            "signum" => Some(Code::Signum),
            _ => None,
        };
        let mut values = values.into_iter();
        let (arg, extra) = (values.next(), values.next());
        let num = match (name.as_str(), arg, extra) {
            ("sin_cos", None, _) => {
                let (s, c) = self.builder.sin_cos(x);
                return Ok(Value::Tuple(vec![Value::Num(s), Value::Num(c)]));
            }
            (_, None, _) if unary.is_some() => {
                let code = unary.unwrap_or(Code::Abs);
                self.builder.unary(code, x)
            }
            ("powi", Some(n), None) => match number(n)? {
                Val::Const(n) if n.fract() == 0.0 && n.abs() <= f64::from(i32::MAX) => {
                    self.builder.powi(x, n as i32)
                }
                other => return error(format_args!("`powi` of the exponent {other:?}")),
            },
            ("powf", Some(y), None) => self.builder.powf(x, number(y)?),
            ("atan2", Some(y), None) => self.builder.op(Code::Atan2, x, number(y)?),
            ("hypot", Some(y), None) => self.builder.op(Code::Hypot, x, number(y)?),
            _ => return error(format_args!("the method call `.{name}({})`", args.stream())),
        };
        Ok(Value::Num(num))
    }
}

/// A `let` pattern: a name, a tuple of patterns, or `Self { a, .. }`.
fn pattern(c: &mut Cursor) -> Result<Pattern> {
    match c.next() {
        Some(TokenTree::Ident(name)) if name == "Self" => {
            let Some(TokenTree::Group(g)) = c.next() else {
                return error("`Self` without its fields");
            };
            let mut names = Vec::new();
            for token in g.stream() {
                match token {
                    TokenTree::Ident(name) => names.push(name.to_string()),
                    TokenTree::Punct(p) if matches!(p.as_char(), ',' | '.') => {}
                    other => return error(format_args!("the field pattern {other}")),
                }
            }
            Ok(Pattern::Fields(names))
        }
        Some(TokenTree::Ident(name)) if name == "mut" => error("a `let mut` binding"),
        Some(TokenTree::Ident(name)) => Ok(Pattern::Name(name.to_string())),
        Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Parenthesis => {
            let mut patterns = Vec::new();
            for item in split_commas(g) {
                let mut inner = Cursor::new(&item);
                patterns.push(pattern(&mut inner)?);
                inner.end()?;
            }
            Ok(Pattern::Tuple(patterns))
        }
        other => error(format_args!("the pattern {other:?}")),
    }
}

fn number(value: Value) -> Result<Val> {
    match value {
        Value::Num(v) => Ok(v),
        other => error(format_args!("{other:?} where a number belongs")),
    }
}

/// A literal's text without its `f64` suffix and digit separators.
fn digits(l: &Literal) -> String {
    let text = l.to_string();
    let text = text.strip_suffix("f64").unwrap_or(&text);
    text.replace('_', "")
}

/// A float (or integer) literal, as rustc reads it: the nearest f64.
fn float(l: &Literal) -> Result<f64> {
    match digits(l).parse::<f64>() {
        Ok(x) => Ok(x),
        Err(_) => error(format_args!("the literal {l}")),
    }
}

/// An index or tuple field.
fn index(l: &Literal) -> Result<usize> {
    match l.to_string().parse::<usize>() {
        Ok(k) => Ok(k),
        Err(_) => error(format_args!("the index {l}")),
    }
}

/// The group's tokens split at its top-level commas (a trailing comma
/// leaves no empty item).
fn split_commas(g: &Group) -> Vec<Vec<TokenTree>> {
    let mut items = vec![Vec::new()];
    for token in g.stream() {
        match &token {
            TokenTree::Punct(p) if p.as_char() == ',' => items.push(Vec::new()),
            _ => items.last_mut().map_or((), |item| item.push(token)),
        }
    }
    if items.last().is_some_and(Vec::is_empty) {
        items.pop();
    }
    items
}

/// `(x,)` is a tuple of one.
fn ends_with_comma(g: &Group) -> bool {
    matches!(g.stream().into_iter().last(), Some(TokenTree::Punct(p)) if p.as_char() == ',')
}

/// A position in a list of tokens.
struct Cursor<'t> {
    tokens: &'t [TokenTree],
    at: usize,
}

impl<'t> Cursor<'t> {
    fn new(tokens: &'t [TokenTree]) -> Cursor<'t> {
        Cursor { tokens, at: 0 }
    }

    fn peek(&self) -> Option<&'t TokenTree> {
        self.tokens.get(self.at)
    }

    fn advance(&mut self) {
        self.at += 1;
    }

    fn next(&mut self) -> Option<&'t TokenTree> {
        let t = self.tokens.get(self.at);
        self.at += 1;
        t
    }

    /// The next token if it is one of these punctuation marks.
    fn peek_punct(&self, marks: &[char]) -> Option<char> {
        match self.peek() {
            Some(TokenTree::Punct(p)) if marks.contains(&p.as_char()) => Some(p.as_char()),
            _ => None,
        }
    }

    fn punct(&mut self, mark: char) -> Result<()> {
        match self.next() {
            Some(TokenTree::Punct(p)) if p.as_char() == mark => Ok(()),
            other => error(format_args!("`{mark}` expected, found {other:?}")),
        }
    }

    fn keyword(&mut self, word: &str) -> Result<()> {
        match self.next() {
            Some(TokenTree::Ident(i)) if i == word => Ok(()),
            other => error(format_args!("`{word}` expected, found {other:?}")),
        }
    }

    fn end(&self) -> Result<()> {
        match self.peek() {
            None => Ok(()),
            Some(t) => error(format_args!("unexpected `{t}`")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tape::slots::Slots;

    const SLOTS: Slots = Slots {
        m: 2,
        f: 1,
        fields: 2,
    };

    /// Reads the statements, then the expression, and evaluates it at
    /// inputs 1, 2, 3, … in slot order (u = (1, 2), v = 3, …, the fields
    /// `a` and `b` last).
    fn read(statements: &[&str], expression: &str) -> Result<f64> {
        let mut builder = Builder::new(SLOTS.total());
        let start = |i: Input| SLOTS.range(i).start as u32;
        let inputs = Input::ALL.map(|i| (i, start(i), SLOTS.len(i)));
        let fields = [
            ("a".to_owned(), start(Input::Fields)),
            ("b".to_owned(), start(Input::Fields) + 1),
        ];
        let late = [("theta3_dot".to_owned(), start(Input::Udot))];
        let trig = ["trig_u".to_owned(), "trig_v".to_owned()];
        let mut reader = Reader::new(&mut builder, inputs, trig, fields, late);
        for s in statements {
            let tokens: TokenStream = s
                .parse()
                .map_err(|e: proc_macro2::LexError| CompileError::new(e.to_string()))?;
            reader.statement(&tokens)?;
        }
        let v = reader.value(expression)?;
        drop(reader);
        let values: Vec<f64> = (1..=SLOTS.total()).map(|k| k as f64).collect();
        Ok(builder.evaluate(&values, v))
    }

    fn inputs() -> (f64, f64, f64, f64) {
        let total = SLOTS.total() as f64;
        (1.0, 2.0, total - 1.0, total)
    }

    #[test]
    fn rusts_precedence_and_associativity() {
        let (x, y, a, b) = inputs();
        let lets = [
            "let (x, y) = (u[0], u[1]);",
            "let Self { a, b, .. } = *self;",
        ];
        let cases: [(&str, f64); 7] = [
            ("-x.powi(2)", -(x * x)),
            ("(-x).powi(2)", x * x),
            ("-a * b", -a * b),
            ("a - b - x", a - b - x),
            ("a / b * y", a / b * y),
            ("x + y * a - b / x", x + y * a - b / x),
            ("-(a - b) * x.sqrt()", -(a - b) * x.sqrt()),
        ];
        for (expression, expected) in cases {
            let value = read(&lets, expression).expect("a form the emitter writes");
            assert_eq!(value.to_bits(), expected.to_bits(), "{expression}");
        }
    }

    #[test]
    fn tuples_fields_indices_paths_and_late_names() {
        let u = |k: usize| (SLOTS.range(Input::U).start + k + 1) as f64;
        let trig_u1 = SLOTS.range(Input::TrigU).start + 2;
        let (s, c) = ((trig_u1 + 1) as f64, (trig_u1 + 2) as f64);
        let cos_v = (SLOTS.range(Input::TrigV).start + 2) as f64;
        let udot = (SLOTS.range(Input::Udot).start + 1) as f64;
        let lets = [
            "let (s, c) = trig_u[1];",
            "let q = trig_v[0].1;",
            "let (t, w) = u[0].sin_cos();",
        ];
        let value = read(
            &lets,
            "s * c + q - t * w + ::core::f64::consts::PI * theta3_dot",
        )
        .expect("a form the emitter writes");
        let (t, w) = u(0).sin_cos();
        let expected = s * c + cos_v - t * w + std::f64::consts::PI * udot;
        assert_eq!(value.to_bits(), expected.to_bits());
    }

    #[test]
    fn a_form_the_emitter_does_not_write_is_an_error() {
        for (statements, expression) in [
            (vec!["let x = u[5];"], "x"),
            (vec!["let x = u[0].cbrt();"], "x"),
            (vec![], "zz"),
            (vec!["let mut x = u[0];"], "x"),
            (vec!["let (x, y) = u[0];"], "x"),
            (vec!["let x = u[0]"], "x"),
            (vec![], "u[0].powi(u[1])"),
            (vec![], "::core::f64::consts::NOT_A_CONSTANT"),
            (vec![], "u"),
            (vec![], "u[0] u[1]"),
        ] {
            assert!(
                read(&statements, expression).is_err(),
                "{statements:?} then `{expression}` accepted"
            );
        }
    }
}
