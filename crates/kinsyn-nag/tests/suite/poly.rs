//! The polynomial layer: arithmetic against hand expansions, derivatives against finite
//! differences, the straight-line program against term-by-term evaluation, Bézout numbers
//! against hand counts. Then one module per source file of `src/poly/` with tests of its own:
//! the multi-homogeneous assignments, the bounds on expansions, the limits of the Bertini
//! reader, the size of a program.

use kinsyn_nag::poly::{C64, Poly, System};

fn c(re: f64, im: f64) -> C64 {
    C64::new(re, im)
}

#[test]
fn binomial_expansion_by_hand() {
    // (x + 2y)^3 = x^3 + 6x^2y + 12xy^2 + 8y^3.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let p = (&x + &(y.clone() * 2.0)).pow(3);
    let expected = Poly::from_terms(
        2,
        [
            (vec![3, 0], c(1.0, 0.0)),
            (vec![2, 1], c(6.0, 0.0)),
            (vec![1, 2], c(12.0, 0.0)),
            (vec![0, 3], c(8.0, 0.0)),
        ],
    );
    assert_eq!(p, expected);
    assert_eq!(p.total_degree(), 3);
    assert_eq!(p.degree_in(&[1]), 3);
    assert!((&p - &p).is_empty(), "p − p cancels to the zero polynomial");
}

#[test]
fn substitution_and_derivative() {
    // p = x^2 y + i y, x := y + 1 gives y^3 + 2y^2 + (1 + i) y.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let p = &(&x * &x) * &y + y.scale(c(0.0, 1.0));
    let q = p.substitute(0, &(&y + &Poly::real(2, 1.0)));
    let expected = Poly::from_terms(
        2,
        [
            (vec![0, 3], c(1.0, 0.0)),
            (vec![0, 2], c(2.0, 0.0)),
            (vec![0, 1], c(1.0, 1.0)),
        ],
    );
    assert_eq!(q, expected);
    // Derivatives against central differences at a complex point.
    let at = [c(0.3, -0.7), c(1.1, 0.4)];
    for i in 0..2 {
        let h = 1e-6;
        let mut plus = at;
        let mut minus = at;
        plus[i] += h;
        minus[i] -= h;
        let fd = (p.eval(&plus) - p.eval(&minus)) / (2.0 * h);
        assert!((fd - p.derivative(i).eval(&at)).norm() < 1e-8);
    }
}

#[test]
fn program_matches_term_by_term_evaluation() {
    // Cyclic-3 with a complex coefficient added, evaluated both ways.
    let v: Vec<Poly> = (0..3).map(|i| Poly::variable(3, i)).collect();
    let f1 = &v[0] + &v[1] + &v[2];
    let f2 = &v[0] * &v[1] + &v[1] * &v[2] + &v[2] * &v[0] + Poly::constant(3, c(0.5, -2.0));
    let f3 = &(&v[0] * &v[1]) * &v[2] - Poly::real(3, 1.0) + v[0].pow(4);
    let system = System::new(vec!["x".into(), "y".into(), "z".into()], vec![f1, f2, f3]).unwrap();
    let program = system.program();
    let mut ws = program.workspace::<C64>();
    let x = [c(0.2, 0.9), c(-1.3, 0.1), c(0.7, -0.4)];
    let mut values = [C64::default(); 3];
    let mut jac = [C64::default(); 9];
    program.evaluate_with_jacobian(&x, &mut values, &mut jac, &mut ws);
    for (i, p) in system.equations().iter().enumerate() {
        assert!((values[i] - p.eval(&x)).norm() < 1e-14);
        for j in 0..3 {
            assert!((jac[3 * i + j] - p.derivative(j).eval(&x)).norm() < 1e-13);
        }
    }
}

#[test]
fn bezout_numbers_by_hand() {
    // Two bilinear equations in groups {x}, {y}: total degree 2·2 = 4, but the
    // two-homogeneous count is 2 (α β coefficient of (α + β)²).
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let f1 = &x * &y - Poly::real(2, 1.0);
    let f2 = &(&x * &y) + &(x.clone() * 3.0) - Poly::real(2, 2.0);
    let system = System::new(vec!["x".into(), "y".into()], vec![f1, f2]).unwrap();
    assert_eq!(system.bezout_number(), 4);
    let grouped = system.with_groups(vec![vec![0], vec![1]]).unwrap();
    assert_eq!(
        grouped.multihomogeneous_degrees(),
        vec![vec![1, 1], vec![1, 1]]
    );
    assert_eq!(grouped.multihomogeneous_bezout(), Some(2));
    assert!(
        grouped.clone().with_groups(vec![vec![0]]).is_err(),
        "every variable in a group"
    );
}

#[test]
fn homogenisation_per_group() {
    // x^2 y + x in groups {x}, {y}: degrees 2 and 1; x^2 y + x h0 h1.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let p = &(&x * &x) * &y + &x;
    let h = p.homogenize(&[vec![0], vec![1]]);
    let expected = Poly::from_terms(
        4,
        [
            (vec![2, 1, 0, 0], c(1.0, 0.0)),
            (vec![1, 0, 1, 1], c(1.0, 0.0)),
        ],
    );
    assert_eq!(h, expected);
}

/// `System::subsystem`: the equations x·z − 1 and y + 2 of a system in (x, y, z, w), kept in
/// (z, x) and in (x, y, z): by hand, the first becomes z·x − 1 in (z, x) — its value at
/// (z, x) = (2, 3) is 5 — and the second cannot drop y.
#[test]
fn a_subsystem_keeps_the_equations_in_the_variables_named() {
    let v = |i| Poly::variable(4, i);
    let names = ["x", "y", "z", "w"].map(String::from).to_vec();
    let s = System::new(
        names,
        vec![
            &(&v(0) * &v(2)) - &Poly::real(4, 1.0),
            &v(1) + &Poly::real(4, 2.0),
        ],
    )
    .unwrap();
    let sub = s.subsystem(&[0], &[2, 0]).unwrap();
    assert_eq!(sub.variables(), ["z".to_string(), "x".to_string()]);
    assert_eq!(
        sub.evaluate(&[C64::from(2.0), C64::from(3.0)])[0],
        C64::from(5.0)
    );
    assert!(s.subsystem(&[1], &[0, 2]).is_err(), "y left out");
    assert!(s.subsystem(&[2], &[0]).is_err(), "no equation 2");
    let both = s.subsystem(&[0, 1], &[0, 1, 2]).unwrap();
    assert_eq!(both.len(), 2);
}

/// `src/poly/multihomogeneous.rs`: the assignments of equations to variable groups, counted by
/// hand, and the bound on their states.
mod multihomogeneous {
    use kinsyn_nag::poly::multihomogeneous::Assignments;

    /// Two bilinear equations in groups {x}, {y}: the assignments are (x, y) and (y, x), each
    /// of weight 1·1: 2. Three equations of degrees (2, 1) in groups of sizes 2 and 1: the
    /// group of one variable takes one of the three equations (weight 1), the other two go to
    /// the first group (weight 2·2): 3 · 4 = 12.
    #[test]
    fn counts_by_hand() {
        let a = Assignments::new(&[vec![1, 1], vec![1, 1]], &[1, 1]).unwrap();
        assert_eq!(a.count(), 2);
        let b = Assignments::new(&[vec![2, 1], vec![2, 1], vec![2, 1]], &[2, 1]).unwrap();
        assert_eq!(b.count(), 12);
    }

    /// Equations that cannot fill the groups count 0, and no first step completes. Here the
    /// second group (one variable) appears in no equation.
    #[test]
    fn no_assignment_completes_when_a_group_is_left_out() {
        let a = Assignments::new(&[vec![1, 0], vec![1, 0]], &[1, 1]).unwrap();
        assert_eq!(a.count(), 0);
        assert_eq!(a.step(0, 0, 0), None);
    }

    /// Sixteen groups of one variable are 2^16 states, the limit; seventeen are refused. With
    /// every degree 1 the count is the permanent of the all-ones 16 × 16 matrix, 16!.
    #[test]
    fn the_states_are_bounded() {
        let ones = vec![vec![1u32; 16]; 16];
        let a = Assignments::new(&ones, &[1; 16]).unwrap();
        assert_eq!(a.count(), (1..=16u128).product::<u128>());
        assert!(Assignments::new(&vec![vec![1u32; 17]; 17], &[1; 17]).is_none());
    }
}

/// `src/poly/expansion.rs`: the bounds on the terms and the work of products and powers, known
/// before they are multiplied, and the budget of a file's expansions.
mod expansion {
    use kinsyn_nag::poly::Poly;
    use kinsyn_nag::poly::expansion::{
        Estimate, ExpansionBudget, MAX_EXPANSION_WORDS, monomials_at_most, power, product,
    };

    /// `C(n + d, n)` counted by hand: monomials of degree ≤ 2 in two variables are
    /// 1, x, y, x², xy, y² (6); of degree ≤ 50 in three, C(53, 3) = 53·52·51/6 = 23426.
    #[test]
    fn monomial_counts_are_binomials() {
        assert_eq!(monomials_at_most(2, 2, u128::MAX), 6);
        assert_eq!(monomials_at_most(3, 50, u128::MAX), 23_426);
        assert_eq!(monomials_at_most(0, 7, u128::MAX), 1);
        assert_eq!(monomials_at_most(5, 0, u128::MAX), 1);
        assert_eq!(monomials_at_most(3, 50, 100), 100, "capped");
        // C(2000, 1000) is about 2e600: saturates at the cap, no overflow.
        assert_eq!(monomials_at_most(1000, 1000, u128::MAX), u128::MAX);
    }

    fn sum_of_variables_and_one(n: usize) -> Poly {
        (0..n).fold(Poly::real(n, 1.0), |p, i| p + Poly::variable(n, i))
    }

    /// The bound of a power is the true count for (x + y + z + 1)^k, whose terms are every
    /// monomial of degree ≤ k; and the work is what `pow` does, term product by term product.
    #[test]
    fn the_power_bound_holds_and_is_sharp_for_a_full_sum() {
        let p = sum_of_variables_and_one(3);
        for k in [0u32, 1, 2, 5, 12] {
            let e = power(&p, k);
            let expanded = p.pow(k);
            assert_eq!(e.terms, expanded.len() as u128, "k = {k}");
            // Work: a copy of p (4), then p^j · p for j = 1 … k − 1: Σ C(j + 3, 3) · 4.
            let by_hand: u128 = if k == 0 {
                0
            } else {
                4 + (1..u128::from(k))
                    .map(|j| (j + 3) * (j + 2) * (j + 1) / 6 * 4)
                    .sum::<u128>()
            };
            assert_eq!(e.work, by_hand, "k = {k}");
        }
        assert_eq!(power(&p, 50).terms, 23_426);
    }

    /// (x + 1)^k has k + 1 terms (the monomial bound, below C(k + 1, k) = k + 1 as well), and
    /// `pow` costs 2 + Σ_{j<k} 2 (j + 1) = k (k + 1) term products.
    #[test]
    fn the_power_of_a_binomial_costs_quadratic_work() {
        let p = sum_of_variables_and_one(1);
        let e = power(&p, 65_535);
        assert_eq!(e.terms, 65_536);
        assert_eq!(e.work, 65_535 * 65_536);
        assert_eq!(power(&p, 7).terms, p.pow(7).len() as u128);
    }

    /// A product's bound: the pairs of terms, or the monomials when fewer; the work is the
    /// pairs. (x + y)·(x − y) = x² − y²: 4 pairs, 6 monomials of degree ≤ 2, 2 terms.
    #[test]
    fn the_product_bound_is_the_smaller_count() {
        let x = Poly::variable(2, 0);
        let y = Poly::variable(2, 1);
        let e = product(&(&x + &y), &(&x - &y));
        assert_eq!(e, Estimate { terms: 4, work: 4 });
        let s = sum_of_variables_and_one(2).pow(3); // 10 terms of degree ≤ 3
        let e = product(&s, &s);
        assert_eq!(e.work, 100);
        assert_eq!(e.terms, 28, "C(2 + 6, 2) = 28 monomials of degree ≤ 6");
        assert!((&s * &s).len() as u128 <= e.terms);
    }

    /// The budget refuses what exceeds it and spends nothing then.
    #[test]
    fn the_budget_is_spent_in_words() {
        let b = ExpansionBudget::default();
        let total = ExpansionBudget::total_terms(3);
        assert_eq!(total, MAX_EXPANSION_WORDS / 19);
        assert_eq!(b.spend(u128::from(total) + 1, 3), Err(total));
        assert_eq!(b.terms_left(3), total);
        assert_eq!(b.spend(u128::from(total) - 5, 3), Ok(()));
        assert_eq!(b.terms_left(3), 5);
        assert_eq!(b.spend(6, 3), Err(5));
    }
}

/// `src/poly/bertini.rs`: the limits of the reader of Bertini files (nesting, the work of
/// expansions, the size of the program) and how expressions are read.
mod bertini {
    use kinsyn_nag::poly::Poly;
    use kinsyn_nag::poly::bertini::{
        BertiniError, BertiniErrorKind, MAX_NESTING, parse, parse_program,
    };
    use kinsyn_nag::poly::expansion::ExpansionBudget;
    use std::fmt::Write as _;

    fn one(body: &str) -> Result<Poly, BertiniError> {
        parse(&format!(
            "INPUT\n  variable_group x;\n  function f;\n  f = {body};\nEND;\n"
        ))
        .map(|input| input.system.equations()[0].clone())
    }

    fn x_to(k: u32, c: f64) -> Poly {
        Poly::variable(1, 0).pow(k) * c
    }

    /// Powers are right-associative and bind tighter than signs: `x^2^3 = x^(2^3) = x^8`,
    /// `-x^2 = -(x^2)`, `x^-(-2) = x^2`, `2^2^x`… is not a polynomial (the exponent `2^x`
    /// is not a constant). Signs are counted: `- - - x = -x`, `+ - + x = -x`.
    #[test]
    fn signs_and_powers_read_in_loops_keep_their_meaning() {
        assert_eq!(one("x^2^3").unwrap(), x_to(8, 1.0));
        assert_eq!(one("-x^2").unwrap(), x_to(2, -1.0));
        assert_eq!(one("x^-(-2)").unwrap(), x_to(2, 1.0));
        assert_eq!(one("(-x)^3").unwrap(), x_to(3, -1.0));
        assert_eq!(one("- - - x").unwrap(), x_to(1, -1.0));
        assert_eq!(one("+ - + x").unwrap(), x_to(1, -1.0));
        assert_eq!(one("2^-1^2*x + x").unwrap_err().line, 4);
        let e = one("x^2^x").unwrap_err();
        assert!(e.to_string().contains("the power '^x'"), "{e}");
        let e = one("x^2^-1").unwrap_err();
        assert!(e.to_string().contains("the power '^-1'"), "{e}");
    }

    /// Nesting: 128 levels are read, 129 refused, whether parentheses, signs or `^`; on a
    /// thread of 512 KiB of stack (a quarter of a test thread's), so the recursion is shallow.
    #[test]
    fn nesting_is_bounded_and_takes_little_stack() {
        let run = || {
            let parens = |k: usize| format!("{}x{}", "(".repeat(k), ")".repeat(k));
            assert_eq!(one(&parens(MAX_NESTING)).unwrap(), x_to(1, 1.0));
            let deep = one(&parens(MAX_NESTING + 1)).unwrap_err();
            assert!(
                matches!(deep.kind, BertiniErrorKind::Nesting { .. }),
                "{deep}"
            );
            let signs = format!("{}x", "- ".repeat(MAX_NESTING));
            assert_eq!(
                one(&signs).unwrap(),
                x_to(1, 1.0),
                "an even number of signs"
            );
            assert!(one(&format!("- {signs}")).is_err());
            let chain = format!("x{}", "^1".repeat(MAX_NESTING));
            assert_eq!(one(&chain).unwrap(), x_to(1, 1.0));
            assert!(one(&format!("{chain}^1")).is_err());
            // Mixed: each parenthesis and each sign one level.
            let mixed = format!(
                "{}x{}",
                "-(".repeat(MAX_NESTING / 2),
                ")".repeat(MAX_NESTING / 2)
            );
            assert_eq!(one(&mixed).unwrap(), x_to(1, 1.0));
        };
        std::thread::Builder::new()
            .stack_size(512 << 10)
            .spawn(run)
            .unwrap()
            .join()
            .unwrap();
    }

    /// An error quotes at most 60 characters of the expression, then `…`: twenty factors
    /// `x^65535` pass the degree limit 2²⁰ at the seventeenth (17 · 65535 = 1114095), where
    /// the product written so far is 135 characters long.
    #[test]
    fn errors_quote_a_short_excerpt() {
        let body = vec!["x^65535"; 20].join("*");
        let e = one(&body).unwrap_err().to_string();
        assert!(e.contains("1114095"), "{e}");
        assert!(e.contains('…'), "{e}");
        assert!(
            e.chars().count() < 200,
            "{} characters: {e}",
            e.chars().count()
        );
    }

    /// Copies of a subfunction are charged: 2 000 copies of a subfunction of 2 000 terms (four
    /// million term operations in one variable) exceed the 3 947 580 a file may take, and
    /// the refusal names the copy that would exceed it.
    #[test]
    fn copies_of_subfunctions_are_charged() {
        let s: Vec<String> = (0..2000).map(|k| format!("x^{k}")).collect();
        let copies = vec!["s"; 2000].join("+");
        let text = format!(
            "INPUT\n  variable_group x;\n  function f;\n  s = {};\n  f = {copies};\nEND;\n",
            s.join("+")
        );
        let e = parse(&text).unwrap_err();
        assert!(
            matches!(
                e.kind,
                BertiniErrorKind::Work {
                    nvars: 1,
                    total: 3_947_580,
                    ..
                }
            ),
            "{e}"
        );
        assert_eq!(ExpansionBudget::total_terms(1), (1 << 26) / 17);
    }

    /// The program of a parsed system is refused beyond its size limit before it is built:
    /// `Σ (s + 1)(s + 2)` over the terms. A term in 600 variables (their product) counts
    /// 601 · 602 = 361 802; twelve such equations exceed 2²² = 4 194 304.
    #[test]
    fn the_program_size_is_bounded_before_compiling() {
        let names: Vec<String> = (0..600).map(|i| format!("x{i}")).collect();
        let product = names.join("*");
        let functions: Vec<String> = (0..12).map(|i| format!("f{i}")).collect();
        let mut text = format!(
            "INPUT\n  variable_group {};\n  function {};\n  p = {product};\n",
            names.join(", "),
            functions.join(", ")
        );
        for f in &functions {
            let _ = writeln!(text, "  {f} = p;");
        }
        text.push_str("END;\n");
        let input = parse(&text).unwrap();
        assert_eq!(input.system.program_size(), 12 * 601 * 602);
        let e = parse_program(&text).unwrap_err();
        assert!(
            matches!(e.kind, BertiniErrorKind::ProgramSize { .. }),
            "{e}"
        );
    }
}

/// `src/poly/program.rs`: the size of the straight-line program of a sparse system.
mod program {
    use kinsyn_nag::poly::{C64, Poly, Program};

    /// `n` linear equations `x_i + x_(i+1) − i` (cyclically) have the monomials `x_0 … x_(n−1)`
    /// and `1` (the constant terms and every derivative): `n + 1` monomials and `n` factors,
    /// whatever `n`; their Jacobian at any point has ones at `(i, i)` and `(i, i + 1)`.
    #[test]
    fn a_sparse_system_compiles_to_a_sparse_program() {
        let n = 1000;
        let equations: Vec<Poly> = (0..n)
            .map(|i| {
                Poly::variable(n, i) + Poly::variable(n, (i + 1) % n) - Poly::real(n, i as f64)
            })
            .collect();
        let program = Program::new(&equations, n);
        assert_eq!(program.monomial_count(), n + 1);
        assert_eq!(program.factor_count(), n);
        let x: Vec<C64> = (0..n).map(|i| C64::new(i as f64, 1.0)).collect();
        let mut values = vec![C64::new(0.0, 0.0); n];
        let mut jacobian = vec![C64::new(0.0, 0.0); n * n];
        let mut ws = program.workspace();
        program.evaluate_with_jacobian(&x, &mut values, &mut jacobian, &mut ws);
        for i in 0..n {
            let expected = x[i] + x[(i + 1) % n] - C64::new(i as f64, 0.0);
            assert_eq!(values[i], expected);
            for j in 0..n {
                let one = j == i || j == (i + 1) % n;
                assert_eq!(jacobian[i * n + j], C64::new(f64::from(u8::from(one)), 0.0));
            }
        }
    }
}
