#include "obj_mesh.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <system_error>
#include <unordered_map>
#include <utility>

#include "shpack/io/quoted.h"

namespace shpack::scene::detail {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The whitespace-separated tokens of one line, front to back; a token starting with '#'
// ends the line (a comment).
struct Tokens {
  std::string_view rest;
  bool next(std::string_view& token) {
    std::size_t at = 0;
    while (at < rest.size() && is_space(rest[at])) ++at;
    if (at == rest.size() || rest[at] == '#') return false;
    std::size_t end = at;
    while (end < rest.size() && !is_space(rest[end])) ++end;
    token = rest.substr(at, end - at);
    rest.remove_prefix(end);
    return true;
  }
};

// The whole of `token` as a number: from_chars, plus an optional leading '+' (C's strtod
// takes one, from_chars does not).
enum class Parsed : std::uint8_t { Ok, NotANumber, OutOfRange };

template <class T>
Parsed parse_number(std::string_view token, T& v) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return Parsed::NotANumber;
  }
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (token.empty() || end != token.data() + token.size()) return Parsed::NotANumber;
  if (ec == std::errc::result_out_of_range) return Parsed::OutOfRange;
  return ec == std::errc() ? Parsed::Ok : Parsed::NotANumber;
}

std::string number_text(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

constexpr std::int64_t kMaxVertices = std::numeric_limits<std::uint32_t>::max();

// `token` as a finite double into v; the problem if it is not one, else empty.
std::string finite_number(std::string_view token, double& v) {
  const Parsed parsed = parse_number(token, v);
  if (parsed == Parsed::NotANumber) return io::quoted(token, 32) + " is not a number";
  if (parsed == Parsed::OutOfRange || !std::isfinite(v)) return io::quoted(token, 32) + " is not a finite double";
  return {};
}

// An attribute that face references may index (texture coordinates, normals): its values,
// each reference's index (0-based, parallel to the position references), the first line with
// a reference without one, and the range problems of its indices, reported at the end only
// if the file has values at all (a file may name indices of an attribute it never writes).
struct Attribute {
  Attribute(const char* n, const char* p, std::size_t s) : name(n), plural(p), stride(s) {}
  const char* name;    // "texture", "normal"
  const char* plural;  // "texture coordinates", "normals"
  std::size_t stride;  // numbers per value
  std::vector<double> values;
  std::vector<std::uint32_t> refs;
  std::size_t missing_line = 0;
  std::int64_t greatest = -1;
  std::size_t greatest_line = 0, problem_line = 0;
  std::string problem;

  std::int64_t count() const { return static_cast<std::int64_t>(values.size() / stride); }
  bool on_every_reference() const { return count() > 0 && missing_line == 0; }

  // The index text `t` of reference `token` on `line`; so_far: count() when the face began.
  // Returns a malformed index's problem, else empty.
  std::string add(std::string_view token, std::string_view t, std::int64_t so_far, std::size_t line) {
    if (t.empty()) {
      if (missing_line == 0) missing_line = line;
      refs.push_back(0);
      return {};
    }
    std::int64_t i = 0;
    const Parsed parsed = parse_number(t, i);
    if (parsed == Parsed::NotANumber) return io::quoted(token, 32) + " is not a vertex reference";
    if (parsed == Parsed::OutOfRange) return std::string(name) + " index " + io::quoted(t, 32) + " is out of range";
    if (i == 0) return std::string(name) + " index 0 (indices count from 1)";
    std::int64_t index = 0;
    if (i > 0) {
      if (i > kMaxVertices) return std::string(name) + " index " + std::to_string(i) + " is out of range";
      index = i - 1;
      if (index > greatest) {
        greatest = index;
        greatest_line = line;
      }
    } else {
      index = so_far + i;
      if (index < 0 && problem.empty()) {
        problem = std::string(name) + " index " + std::to_string(i) + " is out of range (" + std::to_string(so_far) +
                  " " + plural + " so far)";
        problem_line = line;
      }
      index = std::max<std::int64_t>(index, 0);
    }
    refs.push_back(static_cast<std::uint32_t>(index));
    return {};
  }

  // After the last line: an index out of range of the values, if there are any; else empty.
  std::string range_problem(std::size_t& line) const {
    if (count() == 0) return {};
    if (!problem.empty()) {
      line = problem_line;
      return problem;
    }
    if (greatest < count()) return {};
    line = greatest_line;
    return std::string(name) + " index " + std::to_string(greatest + 1) + " is out of range (the file has " +
           std::to_string(count()) + " " + plural + ")";
  }
};

// A vertex of the output: a distinct (position, texture coordinate, normal) of the faces.
struct Corner {
  std::uint32_t position = 0, texture = 0, normal = 0;
  bool operator==(const Corner&) const = default;
};
struct CornerHash {
  std::size_t operator()(const Corner& c) const noexcept {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::uint32_t v : {c.position, c.texture, c.normal}) h = (h ^ v) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

bool parse_obj(std::string_view text, double max_abs, ObjMesh& out, std::string& error, bool with_uv) {
  out = {};
  // Faces are kept as their vertex references until the end, because a positive reference
  // may name a vertex written later and a quad's split needs its positions.
  std::vector<std::uint32_t> refs;
  std::vector<std::size_t> face_starts;
  std::int64_t greatest = -1;  // the largest positive reference (0-based) and its line
  std::size_t greatest_line = 0;
  // with_uv: the texture coordinates and the normals.
  Attribute texture("texture", "texture coordinates", 2);
  Attribute normal("normal", "normals", 3);
  std::size_t line = 0;
  const auto fail = [&](const std::string& problem) {
    error = "line " + std::to_string(line) + ": " + problem;
    return false;
  };
  while (!text.empty()) {
    ++line;
    const std::size_t eol = text.find('\n');
    Tokens tokens{text.substr(0, eol)};
    text.remove_prefix(eol == std::string_view::npos ? text.size() : eol + 1);
    std::string_view keyword;
    if (!tokens.next(keyword)) continue;
    if (keyword == "v") {
      if (static_cast<std::int64_t>(out.vertices.size() / 3) >= kMaxVertices) return fail("too many vertices");
      for (int k = 0; k < 3; ++k) {
        std::string_view token;
        double v = 0;
        if (!tokens.next(token)) return fail("a vertex needs x, y and z");
        if (const std::string p = finite_number(token, v); !p.empty()) return fail(p);
        if (!(std::fabs(v) <= max_abs))
          return fail(number_text(v) + " is beyond " + number_text(max_abs) + ", the ray tracer's range");
        out.vertices.push_back(v);
      }
    } else if (keyword == "vt" && with_uv) {
      if (texture.count() >= kMaxVertices) return fail("too many texture coordinates");
      for (int k = 0; k < 2; ++k) {
        std::string_view token;
        double v = 0;
        if (!tokens.next(token)) {
          if (k == 0) return fail("a texture coordinate needs u (and v)");
          texture.values.push_back(0.0);  // v is optional, 0 by default (the OBJ specification)
          break;
        }
        if (const std::string p = finite_number(token, v); !p.empty()) return fail(p);
        texture.values.push_back(v);
      }
    } else if (keyword == "vn" && with_uv) {
      if (normal.count() >= kMaxVertices) return fail("too many normals");
      for (int k = 0; k < 3; ++k) {
        std::string_view token;
        double v = 0;
        if (!tokens.next(token)) return fail("a normal needs x, y and z");
        if (const std::string p = finite_number(token, v); !p.empty()) return fail(p);
        normal.values.push_back(v);
      }
    } else if (keyword == "f") {
      const std::size_t start = refs.size();
      const auto so_far = static_cast<std::int64_t>(out.vertices.size() / 3);
      const std::int64_t texture_so_far = texture.count(), normal_so_far = normal.count();
      std::string_view token;
      while (tokens.next(token)) {
        std::int64_t i = 0;
        const Parsed parsed = parse_number(token.substr(0, token.find('/')), i);
        if (parsed == Parsed::NotANumber) return fail(io::quoted(token, 32) + " is not a vertex reference");
        if (parsed == Parsed::OutOfRange) return fail("vertex index " + io::quoted(token, 32) + " is out of range");
        if (i == 0) return fail("vertex index 0 (indices count from 1)");
        std::int64_t index = 0;
        if (i > 0) {
          if (i > kMaxVertices) return fail("vertex index " + std::to_string(i) + " is out of range");
          index = i - 1;
          if (index > greatest) {
            greatest = index;
            greatest_line = line;
          }
        } else {
          index = so_far + i;  // i < 0: relative to the vertices so far
          if (index < 0)
            return fail("vertex index " + std::to_string(i) + " is out of range (" + std::to_string(so_far) +
                        " vertices so far)");
        }
        refs.push_back(static_cast<std::uint32_t>(index));
        if (!with_uv) continue;
        // i/t/n: the texture index between the first and a second '/', the normal's after the
        // second; either empty or absent if none.
        const std::size_t slash = token.find('/');
        const std::string_view rest = slash == std::string_view::npos ? std::string_view() : token.substr(slash + 1);
        const std::size_t second = rest.find('/');
        const std::string_view n = second == std::string_view::npos ? std::string_view() : rest.substr(second + 1);
        if (std::string p = texture.add(token, rest.substr(0, second), texture_so_far, line); !p.empty()) return fail(p);
        if (std::string p = normal.add(token, n, normal_so_far, line); !p.empty()) return fail(p);
      }
      if (refs.size() - start < 3) return fail("a face needs at least 3 vertices");
      face_starts.push_back(start);
    }
    // Anything else (o, g, s, l, p, usemtl, mtllib, ...; vt and vn without with_uv) carries
    // no surface.
  }
  const auto count = static_cast<std::int64_t>(out.vertices.size() / 3);
  if (greatest >= count) {
    line = greatest_line;
    return fail("vertex index " + std::to_string(greatest + 1) + " is out of range (the file has " +
                std::to_string(count) + " vertices)");
  }
  if (face_starts.empty()) {
    error = "no faces";
    return false;
  }
  // with_uv: a vertex per distinct (position, texture coordinate[, normal]) of the faces, in
  // first-use order, when every reference has a texture index (and a normal index: else no
  // normals); `emitted` maps refs to those vertices.
  std::vector<std::uint32_t> emitted;
  std::vector<double> split_vertices;
  if (with_uv) {
    for (const Attribute* a : {&texture, &normal})
      if (std::string problem = a->range_problem(line); !problem.empty()) return fail(problem);
    if (!texture.on_every_reference()) {
      out.uv_missing_line = texture.count() == 0 ? 0 : texture.missing_line;
    } else {
      const bool normals = normal.on_every_reference();
      std::unordered_map<Corner, std::uint32_t, CornerHash> vertex_of;
      vertex_of.reserve(refs.size());
      emitted.reserve(refs.size());
      for (std::size_t r = 0; r < refs.size(); ++r) {
        const Corner key{refs[r], texture.refs[r], normals ? normal.refs[r] : 0};
        const auto [it, added] = vertex_of.emplace(key, static_cast<std::uint32_t>(split_vertices.size() / 3));
        if (added) {
          if (split_vertices.size() / 3 >= static_cast<std::size_t>(kMaxVertices)) {
            error = "line " + std::to_string(line) + ": too many distinct (vertex, texture, normal) corners";
            return false;
          }
          const double* p = &out.vertices[3 * std::size_t{key.position}];
          split_vertices.insert(split_vertices.end(), p, p + 3);
          const double* t = &texture.values[2 * std::size_t{key.texture}];
          out.uv.insert(out.uv.end(), t, t + 2);
          if (normals) {
            const double* nv = &normal.values[3 * std::size_t{key.normal}];
            out.normals.insert(out.normals.end(), nv, nv + 3);
          }
        }
        emitted.push_back(it->second);
      }
    }
  }
  const auto vertex = [&](const std::uint32_t* r) {
    return emitted.empty() ? *r : emitted[static_cast<std::size_t>(r - refs.data())];
  };
  const auto squared_distance = [&](std::uint32_t a, std::uint32_t b) {
    const double* p = &out.vertices[3 * std::size_t{a}];
    const double* q = &out.vertices[3 * std::size_t{b}];
    return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
  };
  std::size_t triangles = 0;
  for (std::size_t f = 0; f < face_starts.size(); ++f)
    triangles += (f + 1 < face_starts.size() ? face_starts[f + 1] : refs.size()) - face_starts[f] - 2;
  out.indices.reserve(3 * triangles);
  for (std::size_t f = 0; f < face_starts.size(); ++f) {
    const std::uint32_t* r = refs.data() + face_starts[f];
    const std::size_t n = (f + 1 < face_starts.size() ? face_starts[f + 1] : refs.size()) - face_starts[f];
    if (n == 4 && !(squared_distance(r[0], r[2]) < squared_distance(r[1], r[3]))) {
      for (const std::size_t k : {0, 1, 3, 1, 2, 3}) out.indices.push_back(vertex(r + k));
      continue;
    }
    for (std::size_t k = 1; k + 1 < n; ++k) {  // a quad split along 0-2, or a fan
      out.indices.push_back(vertex(r));
      out.indices.push_back(vertex(r + k));
      out.indices.push_back(vertex(r + k + 1));
    }
  }
  // out.vertices kept the positions as written until now, for the quads' diagonals.
  if (!emitted.empty()) out.vertices = std::move(split_vertices);
  return true;
}

}  // namespace shpack::scene::detail
