//! BPX `Function` values: arithmetic expressions in `x` with Python syntax and semantics
//! (`+ - * / **`, parentheses, `exp`, `log`, `sqrt`, `tanh`, `cosh`, `sinh`), parsed by
//! recursive descent and evaluated in `f64`.

/// A BPX `Function`: an arithmetic expression in `x` with Python semantics.
#[derive(Clone, Debug)]
pub(super) enum Expr {
    Num(f64),
    X,
    Neg(Box<Expr>),
    Bin(Op, Box<Expr>, Box<Expr>),
    Call(Func, Box<Expr>),
}

#[derive(Clone, Copy, Debug)]
pub(super) enum Op {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
}

#[derive(Clone, Copy, Debug)]
pub(super) enum Func {
    Exp,
    Log,
    Sqrt,
    Tanh,
    Cosh,
    Sinh,
}

impl Expr {
    pub(super) fn parse(text: &str) -> Result<Expr, String> {
        let mut p = ExprParser { s: text.as_bytes(), i: 0 };
        let e = p.expr()?;
        p.ws();
        if p.i < p.s.len() {
            return Err(format!("unexpected {:?} at character {}", &text[p.i..], p.i + 1));
        }
        Ok(e)
    }

    pub(super) fn eval(&self, x: f64) -> f64 {
        match self {
            Expr::Num(v) => *v,
            Expr::X => x,
            Expr::Neg(e) => -e.eval(x),
            Expr::Bin(op, a, b) => {
                let (a, b) = (a.eval(x), b.eval(x));
                match op {
                    Op::Add => a + b,
                    Op::Sub => a - b,
                    Op::Mul => a * b,
                    Op::Div => a / b,
                    Op::Pow => a.powf(b),
                }
            }
            Expr::Call(f, e) => {
                let v = e.eval(x);
                match f {
                    Func::Exp => v.exp(),
                    Func::Log => v.ln(),
                    Func::Sqrt => v.sqrt(),
                    Func::Tanh => v.tanh(),
                    Func::Cosh => v.cosh(),
                    Func::Sinh => v.sinh(),
                }
            }
        }
    }

    pub(super) fn uses_x(&self) -> bool {
        match self {
            Expr::Num(_) => false,
            Expr::X => true,
            Expr::Neg(e) | Expr::Call(_, e) => e.uses_x(),
            Expr::Bin(_, a, b) => a.uses_x() || b.uses_x(),
        }
    }
}

/// Recursive descent over Python's precedence: `+ -` < `* /` < unary `-` < `**` (right
/// associative, with a unary right operand).
struct ExprParser<'a> {
    s: &'a [u8],
    i: usize,
}

impl ExprParser<'_> {
    fn ws(&mut self) {
        while self.i < self.s.len() && self.s[self.i].is_ascii_whitespace() {
            self.i += 1;
        }
    }

    fn rest(&mut self) -> &[u8] {
        self.ws();
        &self.s[self.i..]
    }

    fn eat(&mut self, tok: &str) -> bool {
        if self.rest().starts_with(tok.as_bytes()) {
            self.i += tok.len();
            true
        } else {
            false
        }
    }

    fn expr(&mut self) -> Result<Expr, String> {
        let mut e = self.term()?;
        loop {
            let op = if self.eat("+") {
                Op::Add
            } else if self.eat("-") {
                Op::Sub
            } else {
                return Ok(e);
            };
            e = Expr::Bin(op, Box::new(e), Box::new(self.term()?));
        }
    }

    fn term(&mut self) -> Result<Expr, String> {
        let mut e = self.unary()?;
        loop {
            let rest = self.rest();
            let op = if rest.starts_with(b"**") || rest.starts_with(b"//") {
                return Err(format!("unsupported operator at character {}", self.i + 1));
            } else if self.eat("*") {
                Op::Mul
            } else if self.eat("/") {
                Op::Div
            } else {
                return Ok(e);
            };
            e = Expr::Bin(op, Box::new(e), Box::new(self.unary()?));
        }
    }

    fn unary(&mut self) -> Result<Expr, String> {
        if self.eat("-") {
            Ok(Expr::Neg(Box::new(self.unary()?)))
        } else if self.eat("+") {
            self.unary()
        } else {
            self.power()
        }
    }

    fn power(&mut self) -> Result<Expr, String> {
        let base = self.atom()?;
        if self.eat("**") {
            Ok(Expr::Bin(Op::Pow, Box::new(base), Box::new(self.unary()?)))
        } else {
            Ok(base)
        }
    }

    fn atom(&mut self) -> Result<Expr, String> {
        self.ws();
        let start = self.i;
        match self.s.get(start) {
            None => Err("unexpected end of expression".into()),
            Some(b'(') => {
                self.i += 1;
                let e = self.expr()?;
                if self.eat(")") { Ok(e) } else { Err(format!("missing ')' at character {}", self.i + 1)) }
            }
            Some(c) if c.is_ascii_digit() || *c == b'.' => {
                let s = self.s;
                let mut j = start;
                while j < s.len() && (s[j].is_ascii_digit() || s[j] == b'.') {
                    j += 1;
                }
                if j < s.len() && (s[j] == b'e' || s[j] == b'E') {
                    let mut k = j + 1;
                    if k < s.len() && (s[k] == b'+' || s[k] == b'-') {
                        k += 1;
                    }
                    if k < s.len() && s[k].is_ascii_digit() {
                        while k < s.len() && s[k].is_ascii_digit() {
                            k += 1;
                        }
                        j = k;
                    }
                }
                let text = std::str::from_utf8(&s[start..j]).unwrap_or_default();
                self.i = j;
                text.parse()
                    .map(Expr::Num)
                    .map_err(|_| format!("bad number {text:?} at character {}", start + 1))
            }
            Some(c) if c.is_ascii_alphabetic() || *c == b'_' => {
                let s = self.s;
                let mut j = start;
                while j < s.len() && (s[j].is_ascii_alphanumeric() || s[j] == b'_') {
                    j += 1;
                }
                let name = std::str::from_utf8(&s[start..j]).unwrap_or_default().to_string();
                self.i = j;
                if name == "x" {
                    return Ok(Expr::X);
                }
                let func = match name.as_str() {
                    "exp" => Func::Exp,
                    "log" => Func::Log,
                    "sqrt" => Func::Sqrt,
                    "tanh" => Func::Tanh,
                    "cosh" => Func::Cosh,
                    "sinh" => Func::Sinh,
                    _ => {
                        return Err(format!(
                            "unknown name {name:?} at character {} (the variable is x)",
                            start + 1
                        ));
                    }
                };
                if !self.eat("(") {
                    return Err(format!("expected '(' after {name}"));
                }
                let arg = self.expr()?;
                if !self.eat(")") {
                    return Err(format!(
                        "{name} takes one argument; expected ')' at character {}",
                        self.i + 1
                    ));
                }
                Ok(Expr::Call(func, Box::new(arg)))
            }
            Some(c) => Err(format!("unexpected {:?} at character {}", char::from(*c), start + 1)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn expressions_follow_python() {
        let cases = [
            ("1 + 2 * 3", 0.0, 7.0),
            ("-x**2", 3.0, -9.0),
            ("2 ** -1", 0.0, 0.5),
            ("2 ** 3 ** 2", 0.0, 512.0),
            ("1 / 2", 0.0, 0.5),
            ("(x / 1000) ** 1.5", 4000.0, 8.0),
            ("1.5e-3 * exp(-x) - tanh(0) + cosh(0)", 0.0, 1.0015),
            ("- -x", 2.0, 2.0),
            (".5 + 1.", 0.0, 1.5),
            ("3.3e-14", 0.0, 3.3e-14),
        ];
        for (text, x, want) in cases {
            let got = Expr::parse(text).unwrap().eval(x);
            assert!((got - want).abs() <= 1e-12 * want.abs().max(1.0), "{text}: {got} vs {want}");
        }
        for bad in ["1 +", "foo(x)", "x // 2", "exp(x, 2)", "(x", "x y", "2 * * 3", "y"] {
            assert!(Expr::parse(bad).is_err(), "{bad} should not parse");
        }
        assert!(!Expr::parse("3.3e-14").unwrap().uses_x());
    }
}
