//! The items the attribute emits — and `linkage expand --expanded` prints
//! — assembled with `quote!` from the table of quantities
//! (`quantities.rs`): the inherent functions (`function.rs`,
//! `kinematics.rs`, `generic.rs`), the `Kernels` and `Linkage` impls
//! (`trait_impl.rs`), the symbolic table (`symbolic_table.rs`), the
//! associated constants (`constants.rs`) and, when the attribute has
//! mistakes, the fallback (`fallback.rs`).

mod constants;
mod docs;
mod fallback;
mod function;
mod generic;
mod kinematics;
mod quantities;
mod sensitivity;
mod signature;
mod symbolic_table;
mod trait_impl;

use crate::Unbuilt;
use crate::ast::Input;
use crate::dag::Dag;
use crate::derivatives::Derivatives;
use crate::display::Formatter;
use crate::errors::Errors;
use crate::names::SymbolNames;
use crate::plan::Kernel;
use proc_macro2::TokenStream;
use quantities::{DocContext, QUANTITIES, Quantity, Scalar, Source};
use quote::{format_ident, quote};

/// The whole expansion: the struct unchanged, and either the generated items
/// or, if the attribute has mistakes, every error plus the fallback items
/// so that the rest of the user's code still type-checks.
pub fn expand(attr: TokenStream, item: TokenStream) -> TokenStream {
    let run = run(attr, item.clone());
    match run.result {
        Ok(tokens) => tokens,
        Err(error) => {
            let compile_errors = error.to_compile_error();
            // The struct with the fallback items, or the item as written.
            let item = (run.input.as_ref())
                .map(|input| fallback::fallback(input, &run.unbuilt))
                .unwrap_or(item);
            quote! {
                #item
                #compile_errors
            }
        }
    }
}

/// The pipeline's verdict: the generated items or every error found —
/// always one or the other.
pub struct Run {
    /// The parsed input, if the item is a struct.
    pub input: Option<Input>,
    pub result: Result<TokenStream, syn::Error>,
    /// What the pipeline read of an attribute with mistakes.
    pub unbuilt: Unbuilt,
}

pub fn run(attr: TokenStream, item: TokenStream) -> Run {
    let mut errors = Errors::default();
    let input = Input::parse(attr, item, &mut errors);
    let mut unbuilt = Unbuilt::default();
    let generated = input
        .as_ref()
        .and_then(|input| match crate::build(input, &mut errors) {
            Ok(model) => Some(Generator::new(input, &model).items()),
            Err(partial) => {
                unbuilt = partial;
                None
            }
        });
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
    Run {
        input,
        result,
        unbuilt,
    }
}

/// The items of one model.
struct Generator<'a> {
    input: &'a Input,
    model: &'a Derivatives,
    names: SymbolNames,
    m: usize,
    f: usize,
    np: usize,
    /// The number of parameters differentiated by.
    k: usize,
}

impl<'a> Generator<'a> {
    fn new(input: &'a Input, model: &'a Derivatives) -> Generator<'a> {
        Generator {
            input,
            model,
            names: model.lowered.names(),
            m: model.m(),
            f: model.f(),
            np: model.points.len(),
            k: model.k(),
        }
    }

    fn dims(&self) -> signature::Dims {
        signature::Dims::known(self.m, self.f, self.np, self.k)
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

    fn coordinate_list(&self, range: std::ops::Range<usize>) -> String {
        range
            .map(|k| self.names.coord(k))
            .collect::<Vec<_>>()
            .join(", ")
    }

    fn doc_context(&self) -> DocContext {
        let (m, f) = (self.m, self.f);
        let agreement = match self.model.methods_agree {
            Some(true) => {
                "Expanded symbolically at compile time, γ by method A (Ψ̇_u u̇ + Ψ̇_v v̇), by method B \
                 (the four blocks) and this fused form are the same polynomial in q̇."
            }
            Some(false) => {
                "γ by method A and by method B do not expand to the same polynomial here \
                 (they agree numerically; see the tests)."
            }
            None => "γ was too large to compare the two methods symbolically.",
        };
        DocContext {
            m,
            f,
            u_list: self.coordinate_list(0..m),
            v_list: self.coordinate_list(m..m + f),
            q_list: self.coordinate_list(0..m + f),
            point_list: self
                .model
                .points
                .iter()
                .map(|p| p.name.as_str())
                .collect::<Vec<_>>()
                .join(", "),
            p_list: self.names.params_display().join(", "),
            k: self.k,
            agreement: agreement.to_owned(),
            structure: (self.model.blocks).describe(|k| self.names.coord(k).to_string()),
        }
    }

    /// The documentation of a quantity: its paragraph, then its formulas.
    fn doc(&self, q: &Quantity, context: &DocContext) -> Vec<String> {
        let fmt = self.formatter();
        let mut lines = vec![(q.doc)(context)];
        match q.source {
            Source::Formula(matrix) => {
                lines.push(String::new());
                lines.push(self.formula_block(matrix.of(self.model), &fmt));
            }
            Source::Points(pick) if q.scalar == Scalar::F64 => {
                lines.push(String::new());
                lines.push("```text".to_owned());
                for p in &self.model.points {
                    let ids = [p.position, p.velocity, p.acceleration][pick];
                    lines.push(format!("{}.x = {}", p.name, fmt.format(ids[0])));
                    lines.push(format!("{}.y = {}", p.name, fmt.format(ids[1])));
                }
                lines.push("```".to_owned());
            }
            _ => {}
        }
        lines
    }

    /// The inherent function of a quantity.
    fn inherent(&self, q: &Quantity, context: &DocContext) -> TokenStream {
        let doc = self.doc(q, context);
        if let Some(kernel) = q.kernel() {
            return match kernel {
                Kernel::Kinematics { with_trig } => self.kinematics_function(with_trig, &doc),
                Kernel::SensitivityTerms { with_trig } => {
                    self.sensitivity_terms_function(q, with_trig, &doc)
                }
                _ => self.function(q, &doc, kernel),
            };
        }
        match (q.scalar, q.source) {
            (Scalar::Dual, Source::Formula(matrix)) => self.generic_formula(q, &doc, matrix),
            (Scalar::Dual, Source::Points(_)) => self.generic_points(q, &doc),
            _ => quote!(),
        }
    }

    fn items(&self) -> TokenStream {
        let item = &self.input.item;
        let ty = &item.ident;
        let (impl_generics, ty_generics, where_clause) = item.generics.split_for_impl();
        let context = self.doc_context();
        let functions = QUANTITIES
            .iter()
            .filter(|q| q.function)
            .map(|q| self.inherent(q, &context));
        let (u_names, v_names) = (&self.input.u.items, &self.input.v.items);
        let u_names: Vec<String> = u_names.iter().map(crate::ast::unraw).collect();
        let v_names: Vec<String> = v_names.iter().map(crate::ast::unraw).collect();
        let point_names: Vec<&str> = self.model.points.iter().map(|p| p.name.as_str()).collect();
        let param_names = self.names.params_code();
        let dims = self.dims();
        let names = constants::NAMES.iter().map(|c| {
            let value = match c.per {
                constants::Per::U => quote!([#(#u_names),*]),
                constants::Per::V => quote!([#(#v_names),*]),
                constants::Per::Point => quote!([#(#point_names),*]),
                constants::Per::Param => quote!([#(#param_names),*]),
            };
            c.declare(&dims, value)
        });
        let point_indices = point_indices(self.model.points.iter().map(|p| p.name.as_str()));
        let symbolic = self.symbolic_table();
        let trait_impl = self.trait_impl();
        let symbolic_name = format_ident!("{}", constants::SYMBOLIC);
        let psi_u_blocks = self.psi_u_blocks_constant();
        quote! {
            #item
            const _: () = {
                use ::linkage::nalgebra::{SMatrix, SVector, Vector2};

                // The generated functions are the mechanism's interface: a
                // program uses those it needs (and `automatically_derived`
                // is for trait impls: pasted from `linkage expand
                // --expanded`, rustc warns of it on this one).
                #[allow(dead_code)]
                impl #impl_generics #ty #ty_generics #where_clause {
                    #(#names)*
                    #point_indices
                    #psi_u_blocks

                    #(#functions)*

                    /// Every generated quantity as a readable formula, for printing.
                    pub const #symbolic_name: ::linkage::SymbolicTable = #symbolic;
                }

                #trait_impl
            };
        }
    }
}

/// One associated constant per named point, its index in the arrays of
/// positions, velocities and accelerations: `pose.points[FourBar::C]`.
/// (The error path emits them too, so that code naming points keeps
/// type-checking while the attribute has mistakes.)
///
/// A name that is not an identifier, repeats, or is taken by a generated
/// constant (`SYMBOLIC`, `SENSITIVITY_TRIG_U`, …: [`constants::taken`])
/// gets none: on the error path the names have not been checked, and a bad
/// one must not add an error of its own.
pub(super) fn point_indices<'a>(names: impl Iterator<Item = &'a str>) -> TokenStream {
    let mut seen = std::collections::HashSet::new();
    let usable = |name: &str| syn::parse_str::<syn::Ident>(name).is_ok() && !constants::taken(name);
    let consts = names.enumerate().filter_map(|(i, name)| {
        if !usable(name) || !seen.insert(name.to_owned()) {
            return None;
        }
        let ident = format_ident!("{}", name);
        let doc = format!(" The index of the point `{name}`: `pose.points[Self::{name}]`.");
        Some(quote! {
            #[doc = #doc]
            #[allow(non_upper_case_globals)]
            pub const #ident: usize = #i;
        })
    });
    quote!(#(#consts)*)
}

#[cfg(test)]
mod tests {
    use super::expand;
    use super::quantities::{QUANTITIES, Trait};
    use quote::quote;
    use std::collections::{BTreeMap, BTreeSet};

    /// The functions of an expansion: of its inherent impls, of each trait
    /// impl by the trait's name, and the keys of its symbolic table.
    type Inventory = (
        BTreeSet<String>,
        BTreeMap<String, BTreeSet<String>>,
        BTreeSet<String>,
    );

    fn inventory(file: &syn::File) -> Inventory {
        let (mut inherent, mut in_trait) = (BTreeSet::new(), BTreeMap::new());
        let mut impls = Vec::new();
        for item in &file.items {
            if let syn::Item::Const(c) = item {
                if let syn::Expr::Block(block) = &*c.expr {
                    for stmt in &block.block.stmts {
                        if let syn::Stmt::Item(syn::Item::Impl(i)) = stmt {
                            impls.push(i.clone());
                        }
                    }
                }
            }
        }
        for i in &impls {
            let names = i.items.iter().filter_map(|it| match it {
                syn::ImplItem::Fn(f) => Some(f.sig.ident.to_string()),
                _ => None,
            });
            if let Some((_, path, _)) = &i.trait_ {
                let name = path.segments.last().map(|s| s.ident.to_string());
                in_trait
                    .entry(name.unwrap_or_default())
                    .or_insert_with(BTreeSet::new)
                    .extend(names);
            } else {
                inherent.extend(names);
            }
        }
        let text = quote!(#file).to_string();
        let keys = text
            .split("key : \"")
            .skip(1)
            .filter_map(|rest| rest.split('"').next())
            .map(str::to_owned)
            .collect();
        (inherent, in_trait, keys)
    }

    /// Adding a quantity is one entry of the table: every entry appears,
    /// as its flags say, in the inherent items, its trait's impl, the
    /// fallback's inherent items and trait impls, and the symbolic table —
    /// and nothing else does (but the parameters' getter and setter, which
    /// are the struct's fields rather than formulas).
    #[test]
    fn every_quantity_of_the_table_is_generated_everywhere() {
        let good = syn::parse_str::<syn::File>(&fourbar_expansion()).unwrap();
        let broken = expand(
            quote!(
                u = [theta3, theta4],
                v = [theta2],
                closure = [l2 * thta3.cos(), l2 * theta4.sin()]
            ),
            quote!(
                pub struct FourBar {
                    pub l2: f64,
                }
            ),
        );
        let broken: syn::File = syn::parse2(broken).unwrap();
        let functions: BTreeSet<String> = QUANTITIES
            .iter()
            .filter(|q| q.function)
            .map(|q| q.name.to_owned())
            .collect();
        let of = |which: Trait| -> BTreeSet<String> {
            QUANTITIES
                .iter()
                .filter(|q| q.in_trait == Some(which))
                .map(|q| q.name.to_owned())
                .collect()
        };
        // Besides the quantities, each trait answers with its constants.
        let answering = |which: Trait, constants: &[super::constants::Constant]| {
            let mut names = of(which);
            names.extend(constants.iter().map(|c| c.name.to_lowercase()));
            names
        };
        use super::constants::{
            PARAM_NAMES, POINT_NAMES, SENSITIVITY_TRIG, TRIG, U_NAMES, V_NAMES,
        };
        let mut sensitivities = answering(Trait::Sensitivities, &[PARAM_NAMES]);
        sensitivities.extend(["params".to_owned(), "set_params".to_owned()]);
        let kernels = [U_NAMES, V_NAMES, POINT_NAMES, TRIG[0], TRIG[1]];
        let in_trait = BTreeMap::from([
            ("Kernels".to_owned(), answering(Trait::Kernels, &kernels)),
            ("Linkage".to_owned(), BTreeSet::new()),
            (
                "SensitivityKernel".to_owned(),
                answering(Trait::SensitivityKernel, &SENSITIVITY_TRIG),
            ),
            ("Sensitivities".to_owned(), sensitivities),
        ]);
        let keys: BTreeSet<String> = QUANTITIES
            .iter()
            .filter_map(|q| q.key.map(str::to_owned))
            .collect();
        let (good_inherent, good_trait, good_keys) = inventory(&good);
        assert_eq!(good_inherent, functions);
        assert_eq!(good_trait, in_trait);
        assert_eq!(good_keys, keys);
        // The fallback leaves the flags of the carried sines and cosines to
        // the traits' defaults (none carried).
        let mut without_flags = in_trait.clone();
        for (which, flags) in [("Kernels", TRIG), ("SensitivityKernel", SENSITIVITY_TRIG)] {
            for flag in flags {
                without_flags
                    .get_mut(which)
                    .map(|f| f.remove(&flag.name.to_lowercase()));
            }
        }
        let (fallback_inherent, fallback_trait, _) = inventory(&broken);
        assert_eq!(fallback_inherent, functions);
        assert_eq!(fallback_trait, without_flags);
        assert!(
            quote!(#broken).to_string().contains("compile_error"),
            "the broken attribute reports its mistake"
        );
    }

    /// A point named like a generated constant gets no index constant: the
    /// name is declared once in the struct's inherent items, by the
    /// generated constant, whether the attribute has a mistake or not.
    #[test]
    fn a_point_named_like_a_generated_constant_is_declared_once() {
        let names = super::constants::all().map(|c| c.name);
        for name in names.chain([super::constants::SYMBOLIC]) {
            for theta3 in ["theta3", "thta3"] {
                let point = quote::format_ident!("{}", name);
                let theta3 = quote::format_ident!("{}", theta3);
                let tokens = expand(
                    quote!(
                        u = [theta3],
                        v = [theta2],
                        points = [#point = (l2 * theta2.cos(), l2 * theta2.sin())],
                        closure = [l2 * theta2.cos() + l3 * #theta3.cos()]
                    ),
                    quote!(
                        pub struct Bar {
                            pub l2: f64,
                            pub l3: f64,
                        }
                    ),
                );
                let file: syn::File = syn::parse2(tokens).unwrap();
                let mut declared = 0;
                for item in &file.items {
                    let syn::Item::Const(c) = item else { continue };
                    let syn::Expr::Block(block) = &*c.expr else {
                        continue;
                    };
                    for stmt in &block.block.stmts {
                        let syn::Stmt::Item(syn::Item::Impl(i)) = stmt else {
                            continue;
                        };
                        declared += (i.items.iter())
                            .filter(|it| matches!(it, syn::ImplItem::Const(c) if c.ident == name))
                            .filter(|_| i.trait_.is_none())
                            .count();
                    }
                }
                assert_eq!(declared, 1, "`{name}` with `{theta3}` in the closure");
            }
        }
    }

    /// On the error path, where the equations were lowered, k is the
    /// number of parameters the pipeline resolved: a field whose uses
    /// cancel (`l1 - l1`) is none, as it is none without the mistake (here
    /// a reserved name for a point).
    #[test]
    fn the_fallbacks_k_is_the_parameters_resolved() {
        let tokens = expand(
            quote!(
                u = [theta3],
                v = [theta2],
                points = [params = (l2 * theta2.cos(), l2 * theta2.sin())],
                closure = [l2 * theta2.cos() + l3 * theta3.cos() + l1 - l1]
            ),
            quote!(
                pub struct Bar {
                    pub l1: f64,
                    pub l2: f64,
                    pub l3: f64,
                }
            ),
        );
        let text = tokens.to_string();
        assert!(text.contains("compile_error"), "the mistake is reported");
        assert!(
            text.contains("const PARAM_NAMES : [& 'static str ; 2]"),
            "{text}"
        );
    }

    /// The f64 functions of the table are the plan's kernels, in the same
    /// order and under the same names: what each computes is planned in
    /// one place (`crate::plan`), which the tapes compile too.
    #[test]
    fn the_tables_kernels_are_the_plans() {
        use crate::plan::Kernel;
        let kernels: Vec<Kernel> = QUANTITIES.iter().filter_map(|q| q.kernel()).collect();
        assert_eq!(kernels, Kernel::ALL);
        for q in QUANTITIES {
            if let Some(kernel) = q.kernel() {
                assert_eq!(kernel.name(), q.name);
            }
        }
    }

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
    /// `LINKAGE_BLESS=1 cargo test -p linkage-symbolic snapshot` rewrites it.
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

    /// Shared subexpressions everywhere: in every function of the
    /// expansion, a product bound to a `let` (`let l3_c_theta3 = l3 *
    /// c_theta3;`) is written nowhere else in that function — a later
    /// product containing its factors (γ's `l3·cos θ3·θ̇3²` in the fused
    /// kernel) uses the name.
    #[test]
    fn a_named_product_is_never_written_out_again() {
        let text = fourbar_expansion();
        let mut checked = 0;
        for body in text.split("pub fn ").skip(1) {
            let body = body.split("\n        }\n").next().unwrap_or(body);
            for line in body.lines() {
                let Some((name, value)) = line
                    .trim()
                    .strip_prefix("let ")
                    .and_then(|l| l.split_once(" = "))
                else {
                    continue;
                };
                let value = value.trim_end_matches(';');
                let is_product = value.split(" * ").count() > 1
                    && value
                        .split(" * ")
                        .all(|f| f.chars().all(|c| c.is_alphanumeric() || c == '_'));
                if !is_product {
                    continue;
                }
                // The product itself, not part of longer factors
                // (`l3_s_theta3 * theta3_dot` in `l3_s_theta3 * theta3_dot.powi(2)`,
                // `s_theta3 * theta3_dot` in `l3_s_theta3 * theta3_dot`).
                let whole = body
                    .match_indices(value)
                    .filter(|(at, _)| {
                        let previous = body[..*at].chars().next_back();
                        let next = body[at + value.len()..].chars().next();
                        !previous.is_some_and(|c| c.is_alphanumeric() || c == '_')
                            && !next.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == '.')
                    })
                    .count();
                assert_eq!(
                    whole, 1,
                    "`{value}` is bound to `{name}` but written out again in:\n{body}"
                );
                checked += 1;
            }
        }
        assert!(checked >= 6, "only {checked} named products seen");
        assert!(text.contains("gamma[0] = -l3_c_theta3 * theta3_dot.powi(2)"));
    }

    /// The excerpts of generated code in the guide (its `text` blocks that
    /// begin with a doc comment) are the expansion's own lines, indentation aside: the guide
    /// shows what the macro emits today.
    #[test]
    fn the_guides_excerpts_are_the_generated_code() {
        let guide = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/guide.md"),
        )
        .expect("docs/guide.md");
        let trimmed = |lines: &[&str]| -> Vec<String> {
            lines
                .iter()
                .map(|l| l.trim().to_owned())
                .filter(|l| !l.is_empty())
                .collect()
        };
        let text = fourbar_expansion();
        let expansion = trimmed(&text.lines().collect::<Vec<_>>());
        let mut excerpts = 0;
        let mut lines = guide.lines();
        while lines.any(|l| l.starts_with("```text")) {
            let block: Vec<&str> = lines.by_ref().take_while(|l| *l != "```").collect();
            if !block
                .first()
                .is_some_and(|l| l.trim_start().starts_with("///"))
            {
                continue;
            }
            let excerpt = trimmed(&block);
            assert!(
                expansion
                    .windows(excerpt.len())
                    .any(|w| w == excerpt.as_slice()),
                "an excerpt of the guide is not in the expansion:\n{}",
                excerpt.join("\n")
            );
            excerpts += 1;
        }
        assert_eq!(excerpts, 2, "the guide shows Ψ_u and γ");
    }
}
