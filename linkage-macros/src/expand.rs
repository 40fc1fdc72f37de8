//! Stage 5: the items the attribute emits, assembled with `quote!`.

use linkage_symbolic::ast::Input;
use linkage_symbolic::dag::{Dag, Id};
use linkage_symbolic::derivatives::{Derivatives, Matrix};
use linkage_symbolic::display::Formatter;
use linkage_symbolic::emit::{Body, Mode, Reads, emit};
use linkage_symbolic::errors::Errors;
use linkage_symbolic::names::SymbolNames;
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

/// The whole expansion: the struct unchanged, and either the generated items
/// or, if the attribute has mistakes, every error plus a stub implementation
/// so that the rest of the user's code still type-checks.
pub fn expand(attr: TokenStream, item: TokenStream) -> TokenStream {
    let (input, result) = run(attr, item.clone());
    match result {
        Ok(tokens) => tokens,
        Err(error) => {
            let compile_errors = error.to_compile_error();
            // The struct with stub items, or the item as written.
            let item = input.as_ref().map(stub).unwrap_or(item);
            quote! {
                #item
                #compile_errors
            }
        }
    }
}

/// The pipeline's verdict: the parsed input, if the item is a struct, and
/// the generated items or every error found — always one or the other.
pub fn run(
    attr: TokenStream,
    item: TokenStream,
) -> (Option<Input>, Result<TokenStream, syn::Error>) {
    let mut errors = Errors::default();
    let input = Input::parse(attr, item, &mut errors);
    let generated = input
        .as_ref()
        .and_then(|input| generate(input, &mut errors));
    let result = match (errors.combined(), generated) {
        (None, Some(tokens)) => Ok(tokens),
        (Some(error), _) => Err(error),
        // Every path that gives up records why; should one not, the user
        // still gets an error rather than a struct without its methods.
        (None, None) => Err(syn::Error::new(
            proc_macro2::Span::call_site(),
            "#[linkage::linkage(...)] could not read this attribute (an internal \
             error: please report it with the attribute)",
        )),
    };
    (input, result)
}

fn generate(input: &Input, errors: &mut Errors) -> Option<TokenStream> {
    let model = linkage_symbolic::build(input, errors)?;
    Some(Generator::new(input, &model).items())
}

/// For a struct whose attribute has errors: every generated item, with
/// bodies that never run (the build fails) and generic in the dimensions, so
/// that whatever sizes the user's other code passes it still type-checks and
/// only the attribute's real mistakes are reported.
fn stub(input: &Input) -> TokenStream {
    let item = &input.item;
    let ty = &item.ident;
    let (impl_generics, ty_generics, where_clause) = item.generics.split_for_impl();
    let mut generics = item.generics.clone();
    generics.params.push(syn::parse_quote!(const __M: usize));
    generics.params.push(syn::parse_quote!(const __F: usize));
    let (trait_generics, _, _) = generics.split_for_impl();
    let np = Literal::usize_unsuffixed(input.points.items.len());
    let name = ty.to_string();
    let never = quote!(::core::unimplemented!(
        "#[linkage::linkage] on this struct has errors"
    ));
    let inherent = stub_signatures(&quote!(M), &quote!(F), &np).into_iter().map(|(name, ret, extra)| {
        quote! {
            #[allow(clippy::too_many_arguments)]
            pub fn #name<const M: usize, const F: usize>(&self, _u: &SVector<f64, M>, _v: &SVector<f64, F> #extra) -> #ret {
                #never
            }
        }
    });
    let in_trait = stub_signatures(&quote!(__M), &quote!(__F), &np)
        .into_iter()
        .map(|(name, ret, extra)| {
            quote! {
                fn #name(&self, _u: &SVector<f64, __M>, _v: &SVector<f64, __F> #extra) -> #ret {
                    #never
                }
            }
        });
    quote! {
        #item
        const _: () = {
            use ::linkage::nalgebra::{SMatrix, SVector, Vector2};
            #[allow(dead_code, unused_variables)]
            impl #impl_generics #ty #ty_generics #where_clause {
                pub const U_NAMES: &'static [&'static str] = &[];
                pub const V_NAMES: &'static [&'static str] = &[];
                pub const POINT_NAMES: &'static [&'static str] = &[];
                pub const SYMBOLIC: ::linkage::SymbolicTable = ::linkage::SymbolicTable {
                    name: #name,
                    u: &[],
                    v: &[],
                    matrices: &[],
                    methods_agree: ::core::option::Option::None,
                };
                pub fn psi_q<const M: usize, const F: usize, const N: usize>(
                    &self,
                    _u: &SVector<f64, M>,
                    _v: &SVector<f64, F>,
                ) -> SMatrix<f64, M, N> {
                    #never
                }
                #(#inherent)*
                pub fn kinematics<const M: usize, const F: usize>(
                    &self,
                    _u: &SVector<f64, M>,
                    _v: &SVector<f64, F>,
                    _vdot: &SVector<f64, F>,
                    _vddot: &SVector<f64, F>,
                ) -> ::linkage::Kinematics<M, F> {
                    #never
                }
                #[allow(clippy::too_many_arguments)]
                pub fn kinematics_with_trig<const M: usize, const F: usize>(
                    &self,
                    _u: &SVector<f64, M>,
                    _v: &SVector<f64, F>,
                    _trig_u: &[(f64, f64); M],
                    _trig_v: &[(f64, f64); F],
                    _vdot: &SVector<f64, F>,
                    _vddot: &SVector<f64, F>,
                ) -> ::linkage::Kinematics<M, F> {
                    #never
                }
                pub fn psi_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy, const M: usize, const F: usize>(
                    &self,
                    _u: &SVector<D, M>,
                    _v: &SVector<D, F>,
                ) -> SVector<D, M> {
                    #never
                }
                pub fn point_positions_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy, const M: usize, const F: usize>(
                    &self,
                    _u: &SVector<D, M>,
                    _v: &SVector<D, F>,
                ) -> [Vector2<D>; #np] {
                    #never
                }
            }
            #[allow(unused_variables)]
            impl #trait_generics ::linkage::Linkage<__M, __F> for #ty #ty_generics #where_clause {
                type Points = [Vector2<f64>; #np];
                const U_NAMES: [&'static str; __M] = [""; __M];
                const V_NAMES: [&'static str; __F] = [""; __F];
                const POINT_NAMES: &'static [&'static str] = &[];
                const SYMBOLIC: ::linkage::SymbolicTable = Self::SYMBOLIC;
                #(#in_trait)*
                fn kinematics(
                    &self,
                    _u: &SVector<f64, __M>,
                    _v: &SVector<f64, __F>,
                    _vdot: &SVector<f64, __F>,
                    _vddot: &SVector<f64, __F>,
                ) -> ::linkage::Kinematics<__M, __F> {
                    #never
                }
                fn psi_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
                    &self,
                    _u: &SVector<D, __M>,
                    _v: &SVector<D, __F>,
                ) -> SVector<D, __M> {
                    #never
                }
                #[allow(refining_impl_trait)]
                fn point_positions_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
                    &self,
                    _u: &SVector<D, __M>,
                    _v: &SVector<D, __F>,
                ) -> [Vector2<D>; #np] {
                    #never
                }
            }
        };
    }
}

/// The f64 functions of the stub: name, return type and the arguments after
/// `u, v`, for the dimensions `m` and `f`.
fn stub_signatures(
    m: &TokenStream,
    f: &TokenStream,
    np: &Literal,
) -> Vec<(proc_macro2::Ident, TokenStream, TokenStream)> {
    let qdot = quote!(, _udot: &SVector<f64, #m>, _vdot: &SVector<f64, #f>);
    let qddot = quote!(, _udot: &SVector<f64, #m>, _vdot: &SVector<f64, #f>, _uddot: &SVector<f64, #m>, _vddot: &SVector<f64, #f>);
    [
        ("psi", quote!(SVector<f64, #m>), quote!()),
        ("psi_u", quote!(SMatrix<f64, #m, #m>), quote!()),
        ("psi_v", quote!(SMatrix<f64, #m, #f>), quote!()),
        (
            "psi_and_psi_u",
            quote!((SVector<f64, #m>, SMatrix<f64, #m, #m>)),
            quote!(),
        ),
        (
            "psi_u_udot_u",
            quote!(SMatrix<f64, #m, #m>),
            quote!(, _udot: &SVector<f64, #m>),
        ),
        (
            "psi_u_udot_v",
            quote!(SMatrix<f64, #m, #f>),
            quote!(, _udot: &SVector<f64, #m>),
        ),
        (
            "psi_v_vdot_u",
            quote!(SMatrix<f64, #m, #m>),
            quote!(, _vdot: &SVector<f64, #f>),
        ),
        (
            "psi_v_vdot_v",
            quote!(SMatrix<f64, #m, #f>),
            quote!(, _vdot: &SVector<f64, #f>),
        ),
        ("psi_u_dot", quote!(SMatrix<f64, #m, #m>), qdot.clone()),
        ("psi_v_dot", quote!(SMatrix<f64, #m, #f>), qdot.clone()),
        ("gamma", quote!(SVector<f64, #m>), qdot.clone()),
        ("point_positions", quote!([Vector2<f64>; #np]), quote!()),
        ("point_velocities", quote!([Vector2<f64>; #np]), qdot),
        ("point_accelerations", quote!([Vector2<f64>; #np]), qddot),
    ]
    .into_iter()
    .map(|(name, ret, extra)| (format_ident!("{}", name), ret, extra))
    .collect()
}

/// One emitted function: name, doc lines, arguments, result.
struct Function<'a> {
    name: &'static str,
    doc: Vec<String>,
    args: &'a [Arg],
    output: Output,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Arg {
    U,
    V,
    Udot,
    Vdot,
    Uddot,
    Vddot,
}

impl Arg {
    fn name(self) -> &'static str {
        match self {
            Arg::U => "u",
            Arg::V => "v",
            Arg::Udot => "udot",
            Arg::Vdot => "vdot",
            Arg::Uddot => "uddot",
            Arg::Vddot => "vddot",
        }
    }

    fn read(self, r: &Reads) -> bool {
        match self {
            Arg::U => r.u,
            Arg::V => r.v,
            Arg::Udot => r.udot,
            Arg::Vdot => r.vdot,
            Arg::Uddot => r.uddot,
            Arg::Vddot => r.vddot,
        }
    }
}

/// What a function returns.
enum Output {
    /// One matrix (a vector if it has one column), named for the result.
    Matrix(&'static str, Matrix),
    /// A tuple of matrices.
    Tuple(Vec<(&'static str, Matrix)>),
    /// An array of 2-vectors, one per point, with names for the coordinates.
    Points(Vec<([Id; 2], [String; 2])>),
}

struct Generator<'a> {
    input: &'a Input,
    model: &'a Derivatives,
    names: SymbolNames,
    m: usize,
    f: usize,
    np: usize,
}

const U: &[Arg] = &[Arg::U, Arg::V];
const U_UDOT: &[Arg] = &[Arg::U, Arg::V, Arg::Udot];
const U_VDOT: &[Arg] = &[Arg::U, Arg::V, Arg::Vdot];
const U_QDOT: &[Arg] = &[Arg::U, Arg::V, Arg::Udot, Arg::Vdot];
const U_QDOT_QDDOT: &[Arg] = &[Arg::U, Arg::V, Arg::Udot, Arg::Vdot, Arg::Uddot, Arg::Vddot];

impl<'a> Generator<'a> {
    fn new(input: &'a Input, model: &'a Derivatives) -> Generator<'a> {
        Generator {
            input,
            model,
            names: model.lowered.names(),
            m: model.m(),
            f: model.f(),
            np: model.points.len(),
        }
    }

    fn dag(&self) -> &Dag {
        self.model.dag()
    }

    fn formatter(&self) -> Formatter<'_> {
        Formatter {
            dag: self.dag(),
            names: &self.names,
        }
    }

    fn u_list(&self) -> String {
        (0..self.m)
            .map(|k| self.names.coord(k))
            .collect::<Vec<_>>()
            .join(", ")
    }

    fn v_list(&self) -> String {
        (self.m..self.m + self.f)
            .map(|k| self.names.coord(k))
            .collect::<Vec<_>>()
            .join(", ")
    }

    fn q_list(&self) -> String {
        (0..self.m + self.f)
            .map(|k| self.names.coord(k))
            .collect::<Vec<_>>()
            .join(", ")
    }

    fn items(&self) -> TokenStream {
        let item = &self.input.item;
        let ty = &item.ident;
        let (impl_generics, ty_generics, where_clause) = item.generics.split_for_impl();
        let model = self.model;
        let (m, f, n) = (self.m, self.f, self.m + self.f);
        let fmt = self.formatter();
        let u_list = self.u_list();
        let v_list = self.v_list();
        let q_list = self.q_list();

        let mut functions: Vec<TokenStream> = Vec::new();
        let mut add = |function: Function| functions.push(self.function(function));

        add(Function {
            name: "psi",
            doc: vec![
                "Ψ(u, v): the closure equations, zero at every assembled pose.".to_owned(),
                String::new(),
                self.formula_block(&model.psi, &fmt),
            ],
            args: U,
            output: Output::Matrix("psi", model.psi.clone()),
        });
        add(Function {
            name: "psi_q",
            doc: vec![
                format!(
                    "Ψ_q = ∂Ψ/∂q, the {m}×{n} Jacobian with columns q = [{q_list}] (u first, then v)."
                ),
                String::new(),
                self.formula_block(&model.psi_q, &fmt),
            ],
            args: U,
            output: Output::Matrix("psi_q", model.psi_q.clone()),
        });
        add(Function {
            name: "psi_u",
            doc: vec![
                format!("Ψ_u = ∂Ψ/∂u, the {m}×{m} Jacobian with respect to u = [{u_list}]."),
                String::new(),
                self.formula_block(&model.psi_u, &fmt),
            ],
            args: U,
            output: Output::Matrix("psi_u", model.psi_u.clone()),
        });
        add(Function {
            name: "psi_v",
            doc: vec![
                format!("Ψ_v = ∂Ψ/∂v, the {m}×{f} Jacobian with respect to v = [{v_list}]."),
                String::new(),
                self.formula_block(&model.psi_v, &fmt),
            ],
            args: U,
            output: Output::Matrix("psi_v", model.psi_v.clone()),
        });
        add(Function {
            name: "psi_and_psi_u",
            doc: vec![
                "Ψ and Ψ_u together, sharing every sine, cosine and common subexpression: \
                 one Newton–Raphson step's evaluation (see [`Self::psi`] and [`Self::psi_u`])."
                    .to_owned(),
            ],
            args: U,
            output: Output::Tuple(vec![
                ("psi", model.psi.clone()),
                ("psi_u", model.psi_u.clone()),
            ]),
        });
        let second_order = [
            (
                "psi_u_udot_u",
                U_UDOT,
                &model.psi_u_udot_u,
                format!(
                    "([Ψ_u]u̇)_u, the {m}×{m} Jacobian of Ψ_u u̇ with respect to u: the first block of method B (the seed's `Hu_u`)."
                ),
            ),
            (
                "psi_u_udot_v",
                U_UDOT,
                &model.psi_u_udot_v,
                format!(
                    "([Ψ_u]u̇)_v, the {m}×{f} Jacobian of Ψ_u u̇ with respect to v (non-zero when Ψ_u depends on v)."
                ),
            ),
            (
                "psi_v_vdot_u",
                U_VDOT,
                &model.psi_v_vdot_u,
                format!(
                    "([Ψ_v]v̇)_u, the {m}×{m} Jacobian of Ψ_v v̇ with respect to u (non-zero when Ψ_v depends on u)."
                ),
            ),
            (
                "psi_v_vdot_v",
                U_VDOT,
                &model.psi_v_vdot_v,
                format!(
                    "([Ψ_v]v̇)_v, the {m}×{f} Jacobian of Ψ_v v̇ with respect to v (the seed's `Hv_v`)."
                ),
            ),
            (
                "psi_u_dot",
                U_QDOT,
                &model.psi_u_dot,
                format!(
                    "Ψ̇_u = Σₖ ∂Ψ_u/∂qₖ q̇ₖ, the time derivative of Ψ_u ({m}×{m}): method A (the seed's `d_ps_u_pu`)."
                ),
            ),
            (
                "psi_v_dot",
                U_QDOT,
                &model.psi_v_dot,
                format!(
                    "Ψ̇_v = Σₖ ∂Ψ_v/∂qₖ q̇ₖ, the time derivative of Ψ_v ({m}×{f}): method A (the seed's `d_ps_v_pu`)."
                ),
            ),
        ];
        for (name, args, matrix, title) in second_order {
            add(Function {
                name,
                doc: vec![title, String::new(), self.formula_block(matrix, &fmt)],
                args,
                output: Output::Matrix(name, matrix.clone()),
            });
        }
        let agreement = match model.methods_agree {
            Some(true) => {
                "Expanded symbolically at compile time, γ by method A (Ψ̇_u u̇ + Ψ̇_v v̇), by method B \
                           (the four blocks) and this fused form are the same polynomial in q̇."
                    .to_owned()
            }
            Some(false) => {
                "γ by method A and by method B do not expand to the same polynomial here \
                            (they agree numerically; see the tests)."
                    .to_owned()
            }
            None => "γ was too large to compare the two methods symbolically.".to_owned(),
        };
        add(Function {
            name: "gamma",
            doc: vec![
                "γ = (Ψ_q q̇)_q q̇, the convective term of the acceleration equation \
                 Ψ_u ü = −Ψ_v v̈ − γ, in one fused evaluation."
                    .to_owned(),
                String::new(),
                agreement,
                String::new(),
                self.formula_block(&model.gamma, &fmt),
            ],
            args: U_QDOT,
            output: Output::Matrix("gamma", model.gamma.clone()),
        });
        let point_names: Vec<String> = model.points.iter().map(|p| p.name.clone()).collect();
        let lower: Vec<String> = point_names.iter().map(|n| n.to_lowercase()).collect();
        let point_list = point_names.join(", ");
        for (name, suffix, doc, args, pick) in [
            (
                "point_positions",
                "",
                format!("The positions P(q) of the points [{point_list}]."),
                U,
                0usize,
            ),
            (
                "point_velocities",
                "_dot",
                format!("The velocities Ṗ = P_q q̇ of the points [{point_list}]."),
                U_QDOT,
                1,
            ),
            (
                "point_accelerations",
                "_ddot",
                format!("The accelerations P̈ = P_q q̈ + (P_q q̇)_q q̇ of the points [{point_list}]."),
                U_QDOT_QDDOT,
                2,
            ),
        ] {
            let entries: Vec<([Id; 2], [String; 2])> = model
                .points
                .iter()
                .zip(&lower)
                .map(|(p, l)| {
                    let ids = [p.position, p.velocity, p.acceleration][pick];
                    (ids, [format!("{l}_x{suffix}"), format!("{l}_y{suffix}")])
                })
                .collect();
            let mut lines = vec![doc, String::new(), "```text".to_owned()];
            for (p, (ids, _)) in model.points.iter().zip(&entries) {
                lines.push(format!("{}.x = {}", p.name, fmt.format(ids[0])));
                lines.push(format!("{}.y = {}", p.name, fmt.format(ids[1])));
            }
            lines.push("```".to_owned());
            add(Function {
                name,
                doc: lines,
                args,
                output: Output::Points(entries),
            });
        }

        let kinematics = self.kinematics_function(false);
        let kinematics_with_trig = self.kinematics_function(true);
        let generic = self.generic_functions();
        let u_names = self
            .input
            .u
            .items
            .iter()
            .map(linkage_symbolic::lower::unraw);
        let v_names = self
            .input
            .v
            .items
            .iter()
            .map(linkage_symbolic::lower::unraw);
        let (ml, fl, npl) = (
            Literal::usize_unsuffixed(m),
            Literal::usize_unsuffixed(f),
            Literal::usize_unsuffixed(self.np),
        );
        let symbolic = self.symbolic_table();
        let trait_impl = self.trait_impl();
        quote! {
            #item
            const _: () = {
                use ::linkage::nalgebra::{SMatrix, SVector, Vector2};

                #[automatically_derived]
                impl #impl_generics #ty #ty_generics #where_clause {
                    /// The dependent coordinates u, in order.
                    pub const U_NAMES: [&'static str; #ml] = [#(#u_names),*];
                    /// The driving coordinates v, in order.
                    pub const V_NAMES: [&'static str; #fl] = [#(#v_names),*];
                    /// The named points, in order.
                    pub const POINT_NAMES: [&'static str; #npl] = [#(#point_names),*];

                    #(#functions)*

                    #kinematics

                    #kinematics_with_trig

                    #generic

                    /// Every generated quantity as a readable formula, for printing.
                    pub const SYMBOLIC: ::linkage::SymbolicTable = #symbolic;
                }

                #trait_impl
            };
        }
    }

    /// A formula matrix as a doc block.
    fn formula_block(&self, matrix: &Matrix, fmt: &Formatter) -> String {
        let text: Vec<String> = matrix.entries.iter().map(|&e| fmt.format(e)).collect();
        let mut out = vec!["```text".to_owned()];
        out.extend(layout(matrix.rows, matrix.cols, &text));
        out.push("```".to_owned());
        out.join("\n")
    }

    fn function(&self, function: Function) -> TokenStream {
        let name = format_ident!("{}", function.name);
        let (m, f) = (
            Literal::usize_unsuffixed(self.m),
            Literal::usize_unsuffixed(self.f),
        );
        let mut roots = Vec::new();
        let mut hints = Vec::new();
        let mut reserved: Vec<String> = Vec::new();
        match &function.output {
            Output::Matrix(result, matrix) => {
                roots.extend(matrix.entries.iter().copied().filter(|&e| e != Dag::ZERO));
                reserved.push(result.to_string());
            }
            Output::Tuple(parts) => {
                for (result, matrix) in parts {
                    roots.extend(matrix.entries.iter().copied().filter(|&e| e != Dag::ZERO));
                    reserved.push(result.to_string());
                }
            }
            Output::Points(points) => {
                for (ids, names) in points {
                    for c in 0..2 {
                        roots.push(ids[c]);
                        hints.push((ids[c], names[c].clone()));
                    }
                }
            }
        }
        let reserved: Vec<String> = reserved.into_iter().map(|r| self.free_name(&r)).collect();
        let body: Body = emit(
            self.dag(),
            &self.names,
            &roots,
            &hints,
            &reserved,
            Mode::F64,
        );
        let mut values = body.values.iter();
        let mut result_names = reserved.iter();
        let (result, ret) = match &function.output {
            Output::Matrix(_, matrix) => {
                let name = result_names.next().map(String::as_str).unwrap_or("out");
                let (stmts, value, ty) = assemble(matrix, name, &mut values, quote!(f64));
                (quote!(#(#stmts)* #value), ty)
            }
            Output::Tuple(parts) => {
                let mut stmts = Vec::new();
                let mut tuple = Vec::new();
                let mut types = Vec::new();
                for (_, matrix) in parts {
                    let name = result_names.next().map(String::as_str).unwrap_or("out");
                    let (s, value, ty) = assemble(matrix, name, &mut values, quote!(f64));
                    stmts.extend(s);
                    tuple.push(value);
                    types.push(ty);
                }
                (quote!(#(#stmts)* (#(#tuple),*)), quote!((#(#types),*)))
            }
            Output::Points(points) => {
                let mut vectors = Vec::new();
                for _ in points {
                    let x = values.next();
                    let y = values.next();
                    vectors.push(quote!(Vector2::new(#x, #y)));
                }
                let np = Literal::usize_unsuffixed(points.len());
                (quote!([#(#vectors),*]), quote!([Vector2<f64>; #np]))
            }
        };
        let args = function.args.iter().map(|&a| {
            let used = a.read(&body.reads);
            let arg = if used {
                format_ident!("{}", a.name())
            } else {
                format_ident!("_{}", a.name())
            };
            let dim = if matches!(a, Arg::U | Arg::Udot | Arg::Uddot) {
                &m
            } else {
                &f
            };
            quote!(#arg: &SVector<f64, #dim>)
        });
        let doc = wrap_doc(&function.doc.join("\n"));
        let doc_lines = doc.iter().map(|l| format!(" {l}"));
        let statements = &body.statements;
        quote! {
            #(#[doc = #doc_lines])*
            #[must_use]
            pub fn #name(&self, #(#args),*) -> #ret {
                #(#statements)*
                #result
            }
        }
    }

    /// `name`, unless a symbol already has it.
    fn free_name(&self, name: &str) -> String {
        let taken: Vec<String> = self.names.all_code().collect();
        let mut candidate = name.to_owned();
        while taken.contains(&candidate) {
            candidate.push('_');
        }
        candidate
    }

    /// `kinematics`: Ψ, Ψ_u, Ψ_v, the velocity solve and γ in one pass, every
    /// sine, cosine and common subexpression computed once.
    fn kinematics_function(&self, with_trig: bool) -> TokenStream {
        let model = self.model;
        let (m, f) = (self.m, self.f);
        let (ml, fl) = (Literal::usize_unsuffixed(m), Literal::usize_unsuffixed(f));
        let nonzero = |matrix: &Matrix| -> Vec<Id> {
            matrix
                .entries
                .iter()
                .copied()
                .filter(|&e| e != Dag::ZERO)
                .collect()
        };
        let mut first: Vec<Id> = nonzero(&model.psi);
        first.extend(nonzero(&model.psi_u));
        first.extend(nonzero(&model.psi_v));
        let second = nonzero(&model.gamma);
        let locals = [
            "psi", "psi_u", "psi_v", "gamma", "inverse", "rcond", "det", "udot", "uddot",
        ];
        let local: Vec<String> = locals.iter().map(|n| self.free_name(n)).collect();
        let late: Vec<linkage_symbolic::dag::Symbol> = (0..m)
            .map(|k| linkage_symbolic::dag::Symbol::Vel(k as u16))
            .collect();
        let trig_names = [self.free_name("trig_u"), self.free_name("trig_v")];
        let source = linkage_symbolic::emit::TrigSource {
            u: format_ident!("{}", trig_names[0]),
            v: format_ident!("{}", trig_names[1]),
            m,
        };
        let mut reserved = local.clone();
        reserved.extend(trig_names.iter().cloned());
        let phased = linkage_symbolic::emit::emit_phases(
            self.dag(),
            &self.names,
            &[&first, &second],
            &[],
            &reserved,
            Mode::F64,
            &late,
            with_trig.then_some(&source),
        );
        let [psi, psi_u, psi_v, gamma, inverse, rcond, det, udot, uddot] = locals.map(|n| {
            let k = locals.iter().position(|x| *x == n).unwrap_or(0);
            format_ident!("{}", local[k])
        });
        let mut phases = phased.phases.into_iter();
        let (first_statements, first_values) = phases.next().unwrap_or_default();
        let (second_statements, second_values) = phases.next().unwrap_or_default();
        let mut values = first_values.iter();
        let (psi_fill, _, _) = assemble(&model.psi, &psi.to_string(), &mut values, quote!(f64));
        let (psi_u_fill, _, _) =
            assemble(&model.psi_u, &psi_u.to_string(), &mut values, quote!(f64));
        let (psi_v_fill, _, _) =
            assemble(&model.psi_v, &psi_v.to_string(), &mut values, quote!(f64));
        let mut values = second_values.iter();
        let (gamma_fill, _, _) =
            assemble(&model.gamma, &gamma.to_string(), &mut values, quote!(f64));
        let bind = |name: &proc_macro2::Ident, fill: Vec<TokenStream>, ty: TokenStream| {
            if fill.is_empty() {
                quote!(let #name = #ty::zeros();)
            } else {
                quote!(#(#fill)*)
            }
        };
        let psi_bind = bind(&psi, psi_fill, quote!(SVector::<f64, #ml>));
        let psi_u_bind = bind(&psi_u, psi_u_fill, quote!(SMatrix::<f64, #ml, #ml>));
        let psi_v_bind = bind(&psi_v, psi_v_fill, quote!(SMatrix::<f64, #ml, #fl>));
        let gamma_bind = bind(&gamma, gamma_fill, quote!(SVector::<f64, #ml>));
        // The velocities u̇ that γ uses, read from the solved vector.
        let used: Vec<usize> = (0..m)
            .filter(|&k| {
                reaches(
                    self.dag(),
                    &second,
                    linkage_symbolic::dag::Symbol::Vel(k as u16),
                )
            })
            .collect();
        let velocity_names: Vec<proc_macro2::Ident> = used
            .iter()
            .map(|&k| format_ident!("{}", format!("{}_dot", self.model.lowered.coord_name(k))))
            .collect();
        let indices = used.iter().map(|&k| Literal::usize_unsuffixed(k));
        let velocity_bind = match velocity_names.len() {
            0 => quote!(),
            1 => quote!(let #(#velocity_names)* = #(#udot[#indices])*;),
            _ => quote!(let (#(#velocity_names),*) = (#(#udot[#indices]),*);),
        };
        // `field` when the local has the field's name, `field: local` else.
        let field = |name: &str, local: &proc_macro2::Ident| {
            let f = format_ident!("{}", name);
            if *local == name {
                quote!(#f)
            } else {
                quote!(#f: #local)
            }
        };
        let inverse_pattern = {
            let (a, b, c) = (
                field("inverse", &inverse),
                field("rcond", &rcond),
                field("det", &det),
            );
            quote!(#a, #b, #c)
        };
        let fields = [
            ("psi", &psi),
            ("psi_u", &psi_u),
            ("psi_v", &psi_v),
            ("inverse", &inverse),
            ("rcond", &rcond),
            ("det", &det),
            ("udot", &udot),
            ("uddot", &uddot),
        ]
        .map(|(name, local)| field(name, local));
        let prologue = &phased.prologue;
        let reads = phased.reads;
        let arg = |used: bool, name: &str| {
            if used {
                format_ident!("{}", name)
            } else {
                format_ident!("_{}", name)
            }
        };
        let (u_arg, v_arg) = (arg(reads.u, "u"), arg(reads.v, "v"));
        // The body, the same with computed or carried sines and cosines
        // (the prologue reads them from wherever they come from).
        let body = quote! {
            #(#prologue)*
            #(#first_statements)*
            #psi_bind
            #psi_u_bind
            #psi_v_bind
            let ::linkage::Inverse { #inverse_pattern } = ::linkage::invert(&#psi_u);
            let #udot = -(#inverse * (#psi_v * vdot));
            #velocity_bind
            #(#second_statements)*
            #gamma_bind
            let #uddot = -(#inverse * (#psi_v * vddot + #gamma));
            ::linkage::Kinematics { #(#fields),* }
        };
        if with_trig {
            let (trig_u, trig_v) = (&source.u, &source.v);
            let mask = |range: std::ops::Range<usize>| {
                let flags = range.map(|k| phased.trig_coords.contains(&k));
                quote!([#(#flags),*])
            };
            let (mask_u, mask_v) = (mask(0..m), mask(m..m + f));
            return quote! {
                /// Which coordinates of u appear under `sin`/`cos` in
                /// [`Self::kinematics_with_trig`], which reads their sine and
                /// cosine from `trig_u` (the others' entries are not read).
                pub const TRIG_U: [bool; #ml] = #mask_u;
                /// Which coordinates of v appear under `sin`/`cos`, read from
                /// `trig_v`.
                pub const TRIG_V: [bool; #fl] = #mask_v;
                /// [`Self::kinematics`] with the sines and cosines of the
                /// coordinates given (`trig_u[k]` = (sin uₖ, cos uₖ), likewise
                /// `trig_v`) instead of computed: a sweep carries them from pose
                /// to pose by the angle-addition formulas, which costs a few
                /// multiplications instead of a transcendental call.
                #[must_use]
                #[inline(always)]
                #[allow(unused_variables, clippy::too_many_arguments)]
                pub fn kinematics_with_trig(
                    &self,
                    #u_arg: &SVector<f64, #ml>,
                    #v_arg: &SVector<f64, #fl>,
                    #trig_u: &[(f64, f64); #ml],
                    #trig_v: &[(f64, f64); #fl],
                    vdot: &SVector<f64, #fl>,
                    vddot: &SVector<f64, #fl>,
                ) -> ::linkage::Kinematics<#ml, #fl> {
                    #body
                }
            };
        }
        quote! {
            /// Everything at one pose in one pass: Ψ, Ψ_u and Ψ_v; the velocity
            /// u̇ = −Ψ_u⁻¹Ψ_v v̇; γ = (Ψ_q q̇)_q q̇ at that velocity; and the
            /// acceleration ü = −Ψ_u⁻¹(Ψ_v v̈ + γ). Each sine and cosine, and each
            /// subexpression shared between these, is computed once: the fast path
            /// of the runtime's analyses and sweeps.
            #[must_use]
            #[inline]
            pub fn kinematics(
                &self,
                #u_arg: &SVector<f64, #ml>,
                #v_arg: &SVector<f64, #fl>,
                vdot: &SVector<f64, #fl>,
                vddot: &SVector<f64, #fl>,
            ) -> ::linkage::Kinematics<#ml, #fl> {
                #body
            }
        }
    }

    /// `psi_generic` and `point_positions_generic` over dual numbers.
    fn generic_functions(&self) -> TokenStream {
        let (m, f) = (
            Literal::usize_unsuffixed(self.m),
            Literal::usize_unsuffixed(self.f),
        );
        let model = self.model;
        let psi_result = self.free_name("psi");
        let roots: Vec<Id> = model
            .psi
            .entries
            .iter()
            .copied()
            .filter(|&e| e != Dag::ZERO)
            .collect();
        let body = emit(
            self.dag(),
            &self.names,
            &roots,
            &[],
            std::slice::from_ref(&psi_result),
            Mode::Generic,
        );
        let mut values = body.values.iter();
        let (stmts, value, _) = assemble(&model.psi, &psi_result, &mut values, quote!(D));
        let statements = &body.statements;
        let (u, v) = arg_names(&body.reads);

        let point_roots: Vec<Id> = model.points.iter().flat_map(|p| p.position).collect();
        let hints: Vec<(Id, String)> = model
            .points
            .iter()
            .flat_map(|p| {
                let l = p.name.to_lowercase();
                [
                    (p.position[0], format!("{l}_x")),
                    (p.position[1], format!("{l}_y")),
                ]
            })
            .collect();
        let pbody = emit(
            self.dag(),
            &self.names,
            &point_roots,
            &hints,
            &[],
            Mode::Generic,
        );
        let mut pvalues = pbody.values.iter();
        let vectors: Vec<TokenStream> = model
            .points
            .iter()
            .map(|_| {
                let x = pvalues.next();
                let y = pvalues.next();
                quote!(Vector2::new(#x, #y))
            })
            .collect();
        let pstatements = &pbody.statements;
        let (pu, pv) = arg_names(&pbody.reads);
        let np = Literal::usize_unsuffixed(self.np);
        let formula = self.formula_block(&model.psi, &self.formatter());
        let psi_doc = [
            "Ψ(u, v) on any dual number of `num_dual`: the same closure equations as",
            "[`Self::psi`], for derivatives by automatic differentiation (cross-checks,",
            "and the alternative Jacobian source of the runtime).",
            "",
        ]
        .into_iter()
        .map(str::to_owned)
        .chain(formula.lines().map(str::to_owned))
        .map(|l| format!(" {l}"));
        quote! {
            #(#[doc = #psi_doc])*
            #[must_use]
            pub fn psi_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
                &self,
                #u: &SVector<D, #m>,
                #v: &SVector<D, #f>,
            ) -> SVector<D, #m> {
                #(#statements)*
                #(#stmts)*
                #value
            }

            /// The point positions P(q) on any dual number of `num_dual`
            /// (see [`Self::point_positions`]).
            #[must_use]
            pub fn point_positions_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
                &self,
                #pu: &SVector<D, #m>,
                #pv: &SVector<D, #f>,
            ) -> [Vector2<D>; #np] {
                #(#pstatements)*
                [#(#vectors),*]
            }
        }
    }

    fn trait_impl(&self) -> TokenStream {
        let item = &self.input.item;
        let ty = &item.ident;
        let (impl_generics, ty_generics, where_clause) = item.generics.split_for_impl();
        let (m, f, np) = (
            Literal::usize_unsuffixed(self.m),
            Literal::usize_unsuffixed(self.f),
            Literal::usize_unsuffixed(self.np),
        );
        quote! {
            #[automatically_derived]
            impl #impl_generics ::linkage::Linkage<#m, #f> for #ty #ty_generics #where_clause {
                type Points = [Vector2<f64>; #np];
                const U_NAMES: [&'static str; #m] = Self::U_NAMES;
                const V_NAMES: [&'static str; #f] = Self::V_NAMES;
                const POINT_NAMES: &'static [&'static str] = &Self::POINT_NAMES;
                const SYMBOLIC: ::linkage::SymbolicTable = Self::SYMBOLIC;

                fn psi(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>) -> SVector<f64, #m> {
                    Self::psi(self, u, v)
                }
                fn psi_u(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>) -> SMatrix<f64, #m, #m> {
                    Self::psi_u(self, u, v)
                }
                fn psi_v(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>) -> SMatrix<f64, #m, #f> {
                    Self::psi_v(self, u, v)
                }
                fn psi_and_psi_u(
                    &self,
                    u: &SVector<f64, #m>,
                    v: &SVector<f64, #f>,
                ) -> (SVector<f64, #m>, SMatrix<f64, #m, #m>) {
                    Self::psi_and_psi_u(self, u, v)
                }
                fn psi_u_udot_u(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>, udot: &SVector<f64, #m>) -> SMatrix<f64, #m, #m> {
                    Self::psi_u_udot_u(self, u, v, udot)
                }
                fn psi_u_udot_v(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>, udot: &SVector<f64, #m>) -> SMatrix<f64, #m, #f> {
                    Self::psi_u_udot_v(self, u, v, udot)
                }
                fn psi_v_vdot_u(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>, vdot: &SVector<f64, #f>) -> SMatrix<f64, #m, #m> {
                    Self::psi_v_vdot_u(self, u, v, vdot)
                }
                fn psi_v_vdot_v(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>, vdot: &SVector<f64, #f>) -> SMatrix<f64, #m, #f> {
                    Self::psi_v_vdot_v(self, u, v, vdot)
                }
                fn psi_u_dot(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>, udot: &SVector<f64, #m>, vdot: &SVector<f64, #f>) -> SMatrix<f64, #m, #m> {
                    Self::psi_u_dot(self, u, v, udot, vdot)
                }
                fn psi_v_dot(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>, udot: &SVector<f64, #m>, vdot: &SVector<f64, #f>) -> SMatrix<f64, #m, #f> {
                    Self::psi_v_dot(self, u, v, udot, vdot)
                }
                fn gamma(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>, udot: &SVector<f64, #m>, vdot: &SVector<f64, #f>) -> SVector<f64, #m> {
                    Self::gamma(self, u, v, udot, vdot)
                }
                #[inline]
                fn kinematics(
                    &self,
                    u: &SVector<f64, #m>,
                    v: &SVector<f64, #f>,
                    vdot: &SVector<f64, #f>,
                    vddot: &SVector<f64, #f>,
                ) -> ::linkage::Kinematics<#m, #f> {
                    Self::kinematics(self, u, v, vdot, vddot)
                }
                const TRIG_U: [bool; #m] = Self::TRIG_U;
                const TRIG_V: [bool; #f] = Self::TRIG_V;
                #[inline(always)]
                fn kinematics_with_trig(
                    &self,
                    u: &SVector<f64, #m>,
                    v: &SVector<f64, #f>,
                    trig_u: &[(f64, f64); #m],
                    trig_v: &[(f64, f64); #f],
                    vdot: &SVector<f64, #f>,
                    vddot: &SVector<f64, #f>,
                ) -> ::linkage::Kinematics<#m, #f> {
                    Self::kinematics_with_trig(self, u, v, trig_u, trig_v, vdot, vddot)
                }
                fn point_positions(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>) -> [Vector2<f64>; #np] {
                    Self::point_positions(self, u, v)
                }
                fn point_velocities(&self, u: &SVector<f64, #m>, v: &SVector<f64, #f>, udot: &SVector<f64, #m>, vdot: &SVector<f64, #f>) -> [Vector2<f64>; #np] {
                    Self::point_velocities(self, u, v, udot, vdot)
                }
                fn point_accelerations(
                    &self,
                    u: &SVector<f64, #m>,
                    v: &SVector<f64, #f>,
                    udot: &SVector<f64, #m>,
                    vdot: &SVector<f64, #f>,
                    uddot: &SVector<f64, #m>,
                    vddot: &SVector<f64, #f>,
                ) -> [Vector2<f64>; #np] {
                    Self::point_accelerations(self, u, v, udot, vdot, uddot, vddot)
                }
                fn psi_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
                    &self,
                    u: &SVector<D, #m>,
                    v: &SVector<D, #f>,
                ) -> SVector<D, #m> {
                    Self::psi_generic(self, u, v)
                }
                fn point_positions_generic<D: ::linkage::num_dual::DualNum<Primitive = f64> + Copy>(
                    &self,
                    u: &SVector<D, #m>,
                    v: &SVector<D, #f>,
                ) -> impl AsRef<[Vector2<D>]> {
                    Self::point_positions_generic(self, u, v)
                }
            }
        }
    }

    /// The `SymbolicTable` constant: every generated quantity as text.
    fn symbolic_table(&self) -> TokenStream {
        let model = self.model;
        let fmt = self.formatter();
        let (m, f) = (self.m, self.f);
        let eq_labels: Vec<String> = (1..=m).map(|i| format!("Ψ{}", subscript(i))).collect();
        let u_labels: Vec<String> = (0..m).map(|k| self.names.coord(k)).collect();
        let v_labels: Vec<String> = (m..m + f).map(|k| self.names.coord(k)).collect();
        let q_labels: Vec<String> = (0..m + f).map(|k| self.names.coord(k)).collect();
        let mut entries: Vec<TokenStream> = Vec::new();
        let mut add =
            |key: &str, title: &str, matrix: &Matrix, rows: &[String], cols: &[String]| {
                let nonzero = matrix
                    .entries
                    .iter()
                    .enumerate()
                    .filter(|(_, e)| **e != Dag::ZERO)
                    .map(|(k, &e)| {
                        let (i, j) = (
                            Literal::usize_unsuffixed(k / matrix.cols),
                            Literal::usize_unsuffixed(k % matrix.cols),
                        );
                        let text = fmt.format(e);
                        quote!((#i, #j, #text))
                    });
                let (r, c) = (
                    Literal::usize_unsuffixed(matrix.rows),
                    Literal::usize_unsuffixed(matrix.cols),
                );
                entries.push(quote! {
                    ::linkage::SymbolicMatrix {
                        key: #key,
                        title: #title,
                        rows: #r,
                        cols: #c,
                        row_labels: &[#(#rows),*],
                        col_labels: &[#(#cols),*],
                        nonzero: &[#(#nonzero),*],
                    }
                });
            };
        let one = ["".to_owned()];
        add("psi", "Ψ", &model.psi, &eq_labels, &one);
        add("psi_q", "Ψ_q", &model.psi_q, &eq_labels, &q_labels);
        add("psi_u", "Ψ_u", &model.psi_u, &eq_labels, &u_labels);
        add("psi_v", "Ψ_v", &model.psi_v, &eq_labels, &v_labels);
        if let Some(det) = model.det_psi_u {
            let d = Matrix::column(vec![det]);
            add("det_psi_u", "det Ψ_u", &d, &one, &one);
        }
        add(
            "psi_u_udot_u",
            "([Ψ_u]u̇)_u",
            &model.psi_u_udot_u,
            &eq_labels,
            &u_labels,
        );
        add(
            "psi_u_udot_v",
            "([Ψ_u]u̇)_v",
            &model.psi_u_udot_v,
            &eq_labels,
            &v_labels,
        );
        add(
            "psi_v_vdot_u",
            "([Ψ_v]v̇)_u",
            &model.psi_v_vdot_u,
            &eq_labels,
            &u_labels,
        );
        add(
            "psi_v_vdot_v",
            "([Ψ_v]v̇)_v",
            &model.psi_v_vdot_v,
            &eq_labels,
            &v_labels,
        );
        add("psi_u_dot", "Ψ̇_u", &model.psi_u_dot, &eq_labels, &u_labels);
        add("psi_v_dot", "Ψ̇_v", &model.psi_v_dot, &eq_labels, &v_labels);
        add("gamma", "γ = (Ψ_q q̇)_q q̇", &model.gamma, &eq_labels, &one);
        let point_labels: Vec<String> = model.points.iter().map(|p| p.name.clone()).collect();
        let xy = ["x".to_owned(), "y".to_owned()];
        for (key, title, pick) in [
            ("points", "P", 0usize),
            ("point_velocities", "Ṗ", 1),
            ("point_accelerations", "P̈", 2),
        ] {
            let entries: Vec<Id> = model
                .points
                .iter()
                .flat_map(|p| [p.position, p.velocity, p.acceleration][pick])
                .collect();
            let matrix = Matrix {
                rows: model.points.len(),
                cols: 2,
                entries,
            };
            add(key, title, &matrix, &point_labels, &xy);
        }
        let name = self.input.item.ident.to_string();
        let agree = match model.methods_agree {
            Some(b) => quote!(::core::option::Option::Some(#b)),
            None => quote!(::core::option::Option::None),
        };
        quote! {
            ::linkage::SymbolicTable {
                name: #name,
                u: &[#(#u_labels),*],
                v: &[#(#v_labels),*],
                matrices: &[#(#entries),*],
                methods_agree: #agree,
            }
        }
    }
}

fn arg_names(reads: &Reads) -> (proc_macro2::Ident, proc_macro2::Ident) {
    (
        if reads.u {
            format_ident!("u")
        } else {
            format_ident!("_u")
        },
        if reads.v {
            format_ident!("v")
        } else {
            format_ident!("_v")
        },
    )
}

/// The statements filling a result matrix from the emitted values (zero
/// entries left out), the expression naming it, and its type.
fn assemble<'v>(
    matrix: &Matrix,
    name: &str,
    values: &mut impl Iterator<Item = &'v TokenStream>,
    scalar: TokenStream,
) -> (Vec<TokenStream>, TokenStream, TokenStream) {
    let (r, c) = (
        Literal::usize_unsuffixed(matrix.rows),
        Literal::usize_unsuffixed(matrix.cols),
    );
    let is_vector = matrix.cols == 1;
    let (ty, constructor) = if is_vector {
        (quote!(SVector<#scalar, #r>), quote!(SVector::<#scalar, #r>))
    } else {
        (
            quote!(SMatrix<#scalar, #r, #c>),
            quote!(SMatrix::<#scalar, #r, #c>),
        )
    };
    let nonzero: Vec<usize> = (0..matrix.entries.len())
        .filter(|&k| matrix.entries[k] != Dag::ZERO)
        .collect();
    if nonzero.is_empty() {
        return (Vec::new(), quote!(#constructor::zeros()), ty);
    }
    let var = format_ident!("{}", name);
    let mut stmts = vec![quote!(let mut #var = #constructor::zeros();)];
    for k in nonzero {
        let value = values.next();
        let (i, j) = (k / matrix.cols, k % matrix.cols);
        let index = if is_vector {
            let i = Literal::usize_unsuffixed(i);
            quote!(#i)
        } else {
            let (i, j) = (Literal::usize_unsuffixed(i), Literal::usize_unsuffixed(j));
            quote!((#i, #j))
        };
        stmts.push(quote!(#var[#index] = #value;));
    }
    (stmts, quote!(#var), ty)
}

/// Whether any of `roots` depends on the symbol.
fn reaches(dag: &Dag, roots: &[Id], symbol: linkage_symbolic::dag::Symbol) -> bool {
    let mut seen = std::collections::HashSet::new();
    let mut stack: Vec<Id> = roots.to_vec();
    while let Some(id) = stack.pop() {
        if !seen.insert(id) {
            continue;
        }
        match dag.node(id) {
            linkage_symbolic::dag::Node::Sym(s) if *s == symbol => return true,
            node => stack.extend(linkage_symbolic::dag::children(node)),
        }
    }
    false
}

/// A matrix of formulas laid out in aligned columns, or one entry per line
/// when the rows would be too wide to read.
pub fn layout(rows: usize, cols: usize, text: &[String]) -> Vec<String> {
    // A leading space where another entry of the column has a minus sign.
    let text: Vec<String> = (0..rows * cols)
        .map(|k| {
            let j = k % cols;
            let signed = (0..rows).any(|i| text[i * cols + j].starts_with('-'));
            if signed && !text[k].starts_with('-') {
                format!(" {}", text[k])
            } else {
                text[k].clone()
            }
        })
        .collect();
    let width = |s: &str| {
        s.chars()
            .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
            .count()
    };
    let col_width: Vec<usize> = (0..cols)
        .map(|j| {
            (0..rows)
                .map(|i| width(&text[i * cols + j]))
                .max()
                .unwrap_or(0)
        })
        .collect();
    let total: usize = col_width.iter().sum::<usize>() + 3 * cols + 1;
    if total <= 100 {
        (0..rows)
            .map(|i| {
                let cells: Vec<String> = (0..cols)
                    .map(|j| {
                        let t = &text[i * cols + j];
                        format!("{t}{}", " ".repeat(col_width[j] - width(t)))
                    })
                    .collect();
                format!("[ {} ]", cells.join("   ")).trim_end().to_owned()
            })
            .collect()
    } else {
        // Too wide to lay out: the entries one per line, zeros left out.
        let mut out = Vec::new();
        for i in 0..rows {
            for j in 0..cols {
                let t = text[i * cols + j].trim_start();
                if t == "0" {
                    continue;
                }
                if cols == 1 {
                    out.push(format!("[{}] = {t}", i + 1));
                } else {
                    out.push(format!("[{}, {}] = {t}", i + 1, j + 1));
                }
            }
        }
        if out.len() < rows * cols {
            out.push("(entries not listed are 0)".to_owned());
        }
        out
    }
}

/// Doc text with its prose wrapped at 90 columns; code blocks untouched.
fn wrap_doc(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_code = false;
    for line in text.lines() {
        if line.starts_with("```") {
            in_code = !in_code;
            out.push(line.to_owned());
            continue;
        }
        if in_code || line.chars().count() <= 90 {
            out.push(line.to_owned());
            continue;
        }
        let mut current = String::new();
        for word in line.split(' ') {
            if !current.is_empty() && current.chars().count() + 1 + word.chars().count() > 90 {
                out.push(std::mem::take(&mut current));
            }
            if !current.is_empty() {
                current.push(' ');
            }
            current.push_str(word);
        }
        out.push(current);
    }
    out
}

fn subscript(n: usize) -> String {
    const DIGITS: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
    n.to_string()
        .chars()
        .map(|d| DIGITS[d.to_digit(10).unwrap_or(0) as usize])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::expand;
    use quote::quote;

    /// The four-bar of the worksheet, formatted as `cargo expand` shows it.
    pub fn fourbar_expansion() -> String {
        let attr = quote! {
            u = [theta3, theta4],
            v = [theta2],
            points = [
                B = (l2 * theta2.cos(), l2 * theta2.sin()),
                C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
                G2 = (0.5 * B.x, 0.5 * B.y),
                G3 = (0.5 * (B.x + C.x), 0.5 * (B.y + C.y)),
                G4 = (C.x + 0.5 * l4 * theta4.cos(), C.y + 0.5 * l4 * theta4.sin()),
            ],
            closure = [
                l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
                l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
            ],
        };
        let item = quote! {
            #[derive(Clone, Debug)]
            pub struct FourBar { pub l1: f64, pub l2: f64, pub l3: f64, pub l4: f64 }
        };
        let tokens = expand(attr, item);
        let file: syn::File = match syn::parse2(tokens.clone()) {
            Ok(file) => file,
            Err(e) => panic!("the expansion does not parse ({e}):\n{tokens}"),
        };
        prettyplease::unparse(&file)
    }

    /// The expansion of the worksheet's four-bar, formatted with
    /// prettyplease, against the committed snapshot: any change to the
    /// generated code shows up here for review. After a deliberate change,
    /// `LINKAGE_BLESS=1 cargo test -p linkage-macros snapshot` rewrites it.
    #[test]
    fn fourbar_expansion_matches_the_snapshot() {
        let text = fourbar_expansion();
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/snapshots/fourbar.expanded.rs");
        if std::env::var_os("LINKAGE_BLESS").is_some() {
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(&path, &text).unwrap();
        }
        let expected = std::fs::read_to_string(&path).unwrap_or_default();
        if text != expected {
            let line = text
                .lines()
                .zip(expected.lines())
                .position(|(a, b)| a != b)
                .unwrap_or_else(|| text.lines().count().min(expected.lines().count()));
            panic!(
                "the four-bar's expansion differs from {} from line {}:\n  now:      {:?}\n  snapshot: {:?}\n\
                 review the change, then rerun with LINKAGE_BLESS=1",
                path.display(),
                line + 1,
                text.lines().nth(line),
                expected.lines().nth(line)
            );
        }
        assert!(text.contains("let (s_theta3, c_theta3) = theta3.sin_cos();"));
    }
}
