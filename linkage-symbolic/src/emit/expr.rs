//! The emitter's statements and expressions: the `let` bindings of the
//! arguments and of each shared node, and every node as a Rust expression
//! with as few parentheses as its precedence allows.

use super::*;

impl Emitter<'_> {
    /// `let Self { l2, .. } = *self;` and `let (theta3, theta4) = (u[0], u[1]);`
    pub(super) fn prologue(&self, symbols: &[Symbol], reads: &mut Reads) -> Vec<TokenStream> {
        let mut out = Vec::new();
        let m = self.names.m();
        let mut params = Vec::new();
        let mut param_symbols: Vec<u16> = Vec::new();
        let mut sources: [(Vec<TokenStream>, Vec<TokenStream>); 6] = Default::default();
        for &s in symbols {
            let name = ident(&self.names.code(s));
            let (source, k) = match s {
                Symbol::Param(k) => {
                    param_symbols.push(k);
                    params.push(name);
                    continue;
                }
                Symbol::Constant(_) => continue,
                Symbol::Coord(k) => (0, k as usize),
                Symbol::Vel(k) => (2, k as usize),
                Symbol::Acc(k) => (4, k as usize),
            };
            let (source, index) = if k < m {
                (source, k)
            } else {
                (source + 1, k - m)
            };
            let vector = format_ident!("{}", ["u", "v", "udot", "vdot", "uddot", "vddot"][source]);
            let index = Literal::usize_unsuffixed(index);
            sources[source].0.push(quote!(#name));
            sources[source].1.push(quote!(#vector[#index]));
        }
        for (k, (names, values)) in sources.iter().enumerate() {
            if names.is_empty() {
                continue;
            }
            match k {
                0 => reads.u = true,
                1 => reads.v = true,
                2 => reads.udot = true,
                3 => reads.vdot = true,
                4 => reads.uddot = true,
                _ => reads.vddot = true,
            }
            if names.len() == 1 {
                let (n, v) = (&names[0], &values[0]);
                out.push(quote! { let #n = #v; });
            } else {
                out.push(quote! { let (#(#names),*) = (#(#values),*); });
            }
        }
        if !params.is_empty() {
            let line = match self.mode {
                Mode::F64 => quote! { let Self { #(#params,)* .. } = *self; },
                Mode::Generic {
                    params_from_p: false,
                } => {
                    quote! { #(let #params = D::from(self.#params);)* }
                }
                Mode::Generic {
                    params_from_p: true,
                } => {
                    // A field called `params` shadows the argument: bound last.
                    let mut order: Vec<(u16, &syn::Ident)> =
                        param_symbols.iter().copied().zip(&params).collect();
                    order.sort_by_key(|(_, name)| *name == "params");
                    let mut lines = Vec::new();
                    for (k, name) in order {
                        lines.push(match self.names.param_index(k) {
                            Some(i) => {
                                reads.p = true;
                                let i = Literal::usize_unsuffixed(i);
                                quote! { let #name = params[#i]; }
                            }
                            None => quote! { let #name = D::from(self.#name); },
                        });
                    }
                    quote! { #(#lines)* }
                }
            };
            out.insert(0, line);
        }
        out
    }

    /// A readable name built from the node's structure.
    pub(super) fn structural_name(&self, id: Id) -> String {
        if let Some(name) = self.bound.get(&id) {
            return name.clone();
        }
        match self.dag.node(id) {
            Node::Const(c) => {
                let c = c.get();
                if c.fract() == 0.0 && c.abs() < 1e6 {
                    format!("{}{}", if c < 0.0 { "m" } else { "" }, c.abs() as i64)
                } else {
                    "k".to_owned()
                }
            }
            Node::Sym(s) => self.names.code(*s),
            Node::Call(f, a) => {
                let prefix = match f {
                    Func::Sin => "s",
                    Func::Cos => "c",
                    other => other.method(),
                };
                format!("{prefix}_{}", self.structural_name(*a))
            }
            Node::Call2(f, a, b) => {
                let prefix = match f {
                    Func2::Powf => "pow",
                    other => other.method(),
                };
                format!(
                    "{prefix}_{}_{}",
                    self.structural_name(*a),
                    self.structural_name(*b)
                )
            }
            Node::Sum(terms) if terms.len() == 1 => {
                let (c, t) = (terms[0].0.get(), terms[0].1);
                if c == -1.0 {
                    format!("neg_{}", self.structural_name(t))
                } else {
                    format!("k_{}", self.structural_name(t))
                }
            }
            Node::Sum(terms) => {
                let ordered =
                    display_order(self.dag, terms.iter().map(|&(c, t)| (c.get(), t)).collect());
                let mut s = String::new();
                for (k, (c, t)) in ordered.into_iter().enumerate() {
                    let part = if t == Dag::ONE {
                        "1".to_owned()
                    } else {
                        self.structural_name(t)
                    };
                    let joiner = match (k, c < 0.0) {
                        (0, false) => "",
                        (0, true) => "neg_",
                        (_, false) => "_plus_",
                        (_, true) => "_minus_",
                    };
                    s.push_str(joiner);
                    if c.abs() != 1.0 {
                        s.push_str("k_");
                    }
                    s.push_str(&part);
                }
                s
            }
            Node::Prod(factors) => {
                let mut num = Vec::new();
                let mut den = Vec::new();
                for (f, e) in crate::display::factor_order(self.dag, factors) {
                    let base = self.structural_name(f);
                    let text = match e.unsigned_abs() {
                        1 => base,
                        2 => format!("{base}_sq"),
                        3 => format!("{base}_cube"),
                        n => format!("{base}_pow{n}"),
                    };
                    if e > 0 {
                        num.push(text)
                    } else {
                        den.push(text)
                    }
                }
                match (num.is_empty(), den.is_empty()) {
                    (_, true) => num.join("_"),
                    (true, false) => format!("inv_{}", den.join("_")),
                    (false, false) => format!("{}_over_{}", num.join("_"), den.join("_")),
                }
            }
        }
    }

    /// A short name saying what kind of quantity a node is, when its
    /// structure is too long to spell out.
    pub(super) fn kind_name(&self, id: Id) -> String {
        match self.dag.node(id) {
            Node::Sum(_) => "sum".to_owned(),
            Node::Prod(f) if f.iter().any(|&(_, e)| e < 0) => "ratio".to_owned(),
            Node::Prod(_) => "product".to_owned(),
            Node::Call(f, _) => f.method().to_owned(),
            Node::Call2(Func2::Powf, ..) => "power".to_owned(),
            Node::Call2(f, ..) => f.method().to_owned(),
            Node::Const(_) | Node::Sym(_) => "value".to_owned(),
        }
    }

    pub(super) fn literal(&self, c: f64) -> (TokenStream, Prec) {
        let lit = Literal::f64_unsuffixed(c.abs());
        let tokens = match self.mode {
            Mode::F64 if c < 0.0 => quote!(-#lit),
            Mode::F64 => quote!(#lit),
            Mode::Generic { .. } if c < 0.0 => quote!(D::from(-#lit)),
            Mode::Generic { .. } => quote!(D::from(#lit)),
        };
        let prec = match self.mode {
            Mode::F64 if c < 0.0 => Prec::Unary,
            // A bare float literal cannot receive a method call.
            Mode::F64 => Prec::Product,
            Mode::Generic { .. } => Prec::Atom,
        };
        (tokens, prec)
    }

    /// The node as an operand that binds at least as tightly as `at_least`.
    pub(super) fn operand(&self, id: Id, at_least: Prec) -> TokenStream {
        let (tokens, prec) = match self.bound.get(&id) {
            Some(name) => {
                let name = ident(name);
                (quote!(#name), Prec::Atom)
            }
            None => self.definition(id),
        };
        if prec < at_least {
            quote!((#tokens))
        } else {
            tokens
        }
    }

    /// The node as the receiver of a method call. In f64 code a constant
    /// receiver carries its type: `2.0.powf(x)` and `(1.0).atan2(x)` do not
    /// compile (the literal's float type is ambiguous), `2f64.powf(x)` does.
    pub(super) fn receiver(&self, id: Id) -> TokenStream {
        match (self.mode, self.bound.get(&id), self.dag.as_const(id)) {
            (Mode::F64, None, Some(c)) => {
                let lit = Literal::f64_suffixed(c.abs());
                if c < 0.0 {
                    quote!((-#lit))
                } else {
                    quote!(#lit)
                }
            }
            _ => self.operand(id, Prec::Atom),
        }
    }

    /// The expression defining a node (its children by name if bound).
    pub(super) fn definition(&self, id: Id) -> (TokenStream, Prec) {
        match self.dag.node(id) {
            Node::Const(c) => self.literal(c.get()),
            Node::Sym(Symbol::Constant(c)) => {
                let name = format_ident!("{}", c.name());
                match self.mode {
                    Mode::F64 => (quote!(::core::f64::consts::#name), Prec::Atom),
                    Mode::Generic { .. } => {
                        (quote!(D::from(::core::f64::consts::#name)), Prec::Atom)
                    }
                }
            }
            Node::Sym(s) => {
                let name = ident(&self.names.code(*s));
                (quote!(#name), Prec::Atom)
            }
            Node::Sum(terms) => self.sum(terms.iter().map(|&(c, t)| (c.get(), t)).collect()),
            Node::Prod(factors) => (self.product(1.0, factors), Prec::Product),
            Node::Call(f, a) => {
                let arg = self.receiver(*a);
                let method = format_ident!("{}", f.method());
                (quote!(#arg.#method()), Prec::Atom)
            }
            Node::Call2(f, a, b) => {
                let x = self.receiver(*a);
                let tokens = match (f, self.mode) {
                    (Func2::Atan2, _) => {
                        let y = self.operand(*b, Prec::Sum);
                        quote!(#x.atan2(#y))
                    }
                    (Func2::Hypot, Mode::F64) => {
                        let y = self.operand(*b, Prec::Sum);
                        quote!(#x.hypot(#y))
                    }
                    (Func2::Hypot, Mode::Generic { .. }) => {
                        let y = self.operand(*b, Prec::Atom);
                        quote!((#x.powi(2) + #y.powi(2)).sqrt())
                    }
                    (Func2::Powf, Mode::F64) => {
                        let y = self.operand(*b, Prec::Sum);
                        quote!(#x.powf(#y))
                    }
                    (Func2::Powf, Mode::Generic { .. }) => match self.dag.as_const(*b) {
                        Some(c) => {
                            let c = Literal::f64_unsuffixed(c.abs());
                            let c = if self.dag.as_const(*b).is_some_and(|c| c < 0.0) {
                                quote!(-#c)
                            } else {
                                quote!(#c)
                            };
                            quote!(#x.powf(#c))
                        }
                        None => {
                            let y = self.operand(*b, Prec::Sum);
                            quote!(#x.powd(#y))
                        }
                    },
                };
                (tokens, Prec::Atom)
            }
        }
    }

    /// `Σ cᵢ·tᵢ` in reading order.
    pub(super) fn sum(&self, terms: Vec<(f64, Id)>) -> (TokenStream, Prec) {
        let single = terms.len() == 1;
        let ordered = display_order(self.dag, terms);
        let mut out = TokenStream::new();
        for (k, (c, t)) in ordered.into_iter().enumerate() {
            let magnitude = if t == Dag::ONE && k > 0 {
                // `x + 2.0` is valid for `f64` and for a dual number alike.
                let lit = Literal::f64_unsuffixed(c.abs());
                quote!(#lit)
            } else if t == Dag::ONE {
                self.literal(c.abs()).0
            } else {
                self.scaled(c.abs(), t)
            };
            match (k, c < 0.0) {
                (0, false) => out.extend(magnitude),
                (0, true) => out.extend(quote!(-#magnitude)),
                (_, false) => out.extend(quote!(+ #magnitude)),
                (_, true) => out.extend(quote!(- #magnitude)),
            }
        }
        let prec = if !single {
            Prec::Sum
        } else if out.to_string().starts_with('-') {
            Prec::Unary
        } else {
            Prec::Product
        };
        (out, prec)
    }

    /// `c·t` for `c > 0`, as a product chain.
    pub(super) fn scaled(&self, c: f64, t: Id) -> TokenStream {
        if let (None, Node::Prod(factors)) = (self.bound.get(&t), self.dag.node(t)) {
            return self.product(c, factors);
        }
        let operand = self.operand(t, Prec::Product);
        if c == 1.0 {
            return operand;
        }
        let lit = Literal::f64_unsuffixed(c);
        match self.mode {
            Mode::F64 => quote!(#lit * #operand),
            Mode::Generic { .. } => quote!(#operand * #lit),
        }
    }

    /// The named products within `factors`: products already bound to a
    /// `let` whose factors (with their exponents, all positive) all occur in
    /// `factors`, the largest first, disjoint; and the factors left over.
    fn named_subproducts(&self, factors: &[(Id, i32)]) -> (Vec<Id>, Vec<(Id, i32)>) {
        let mut rest = factors.to_vec();
        let mut named = Vec::new();
        loop {
            let within = |sub: &[(Id, i32)]| {
                sub.len() < rest.len() && sub.iter().all(|f| f.1 > 0 && rest.contains(f))
            };
            let best = rest
                .iter()
                .filter_map(|f| self.products.get(f))
                .flatten()
                .filter_map(|&p| match self.dag.node(p) {
                    Node::Prod(sub) if within(sub) => Some((p, sub)),
                    _ => None,
                })
                .max_by_key(|(p, sub)| (sub.len(), std::cmp::Reverse(*p)));
            let Some((p, sub)) = best else {
                return (named, rest);
            };
            rest.retain(|f| !sub.contains(f));
            named.push(p);
        }
    }

    /// `c·Π fᵢ^eᵢ` as `c * a * b / (d * e.powi(2))`, reusing the named
    /// products within it (`l3_c_theta3 * theta3_dot.powi(2)`).
    pub(super) fn product(&self, c: f64, factors: &[(Id, i32)]) -> TokenStream {
        let power = |f: Id, e: u32| -> TokenStream {
            if e == 1 {
                self.operand(f, Prec::Unary)
            } else {
                let base = self.receiver(f);
                let e = Literal::i32_unsuffixed(e as i32);
                quote!(#base.powi(#e))
            }
        };
        let (named, factors) = self.named_subproducts(factors);
        let factors = crate::display::factor_order(self.dag, &factors);
        let numerator: Vec<TokenStream> = named
            .iter()
            .map(|&p| self.operand(p, Prec::Atom))
            .chain(
                factors
                    .iter()
                    .filter(|f| f.1 > 0)
                    .map(|&(f, e)| power(f, e.unsigned_abs())),
            )
            .collect();
        let denominator: Vec<TokenStream> = factors
            .iter()
            .filter(|f| f.1 < 0)
            .map(|&(f, e)| power(f, e.unsigned_abs()))
            .collect();
        let lit = Literal::f64_unsuffixed(c);
        let numerator = join_products(numerator);
        let mut num = match (self.mode, numerator.is_empty(), c == 1.0) {
            (Mode::F64, true, _) => quote!(#lit),
            (Mode::F64, false, true) => numerator.clone(),
            (Mode::F64, false, false) => quote!(#lit * #numerator),
            (Mode::Generic { .. }, true, _) => quote!(D::from(#lit)),
            (Mode::Generic { .. }, false, _) => numerator.clone(),
        };
        match denominator.len() {
            0 => {}
            1 => {
                let d = &denominator[0];
                num = quote!(#num / #d);
            }
            _ => {
                let d = join_products(denominator);
                num = quote!(#num / (#d));
            }
        }
        if matches!(self.mode, Mode::Generic { .. }) && c != 1.0 && !numerator.is_empty() {
            num = quote!(#num * #lit);
        }
        num
    }
}
