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

std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 32;  // a hostile token may be megabytes long
  // Appended piece by piece: g++ 12 at -O3 reports a false -Wrestrict on "'" + string.
  std::string out(1, '\'');
  out.append(token.substr(0, kShown));
  out += token.size() > kShown ? "...'" : "'";
  return out;
}

std::string number_text(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

bool parse_obj(std::string_view text, double max_abs, ObjMesh& out, std::string& error, bool with_uv) {
  out = {};
  // Faces are kept as their vertex references until the end, because a positive reference
  // may name a vertex written later and a quad's split needs its positions.
  std::vector<std::uint32_t> refs;
  std::vector<std::size_t> face_starts;
  std::int64_t greatest = -1;  // the largest positive reference (0-based) and its line
  std::size_t greatest_line = 0;
  constexpr std::int64_t kMaxVertices = std::numeric_limits<std::uint32_t>::max();
  // with_uv: the texture coordinates, each reference's texture index (0-based, parallel to
  // refs), the first line with a reference without one, and the range problems of texture
  // indices, reported at the end only if the file has texture coordinates at all.
  std::vector<double> texcoords;
  std::vector<std::uint32_t> texture_refs;
  std::size_t missing_line = 0;
  std::int64_t greatest_texture = -1;
  std::size_t greatest_texture_line = 0, texture_problem_line = 0;
  std::string texture_problem;
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
        const Parsed parsed = parse_number(token, v);
        if (parsed == Parsed::NotANumber) return fail(quoted(token) + " is not a number");
        if (parsed == Parsed::OutOfRange || !std::isfinite(v)) return fail(quoted(token) + " is not a finite double");
        if (!(std::fabs(v) <= max_abs))
          return fail(number_text(v) + " is beyond " + number_text(max_abs) + ", the ray tracer's range");
        out.vertices.push_back(v);
      }
    } else if (keyword == "vt" && with_uv) {
      if (static_cast<std::int64_t>(texcoords.size() / 2) >= kMaxVertices) return fail("too many texture coordinates");
      for (int k = 0; k < 2; ++k) {
        std::string_view token;
        double v = 0;
        if (!tokens.next(token)) {
          if (k == 0) return fail("a texture coordinate needs u (and v)");
          texcoords.push_back(0.0);  // v is optional, 0 by default (the OBJ specification)
          break;
        }
        const Parsed parsed = parse_number(token, v);
        if (parsed == Parsed::NotANumber) return fail(quoted(token) + " is not a number");
        if (parsed == Parsed::OutOfRange || !std::isfinite(v)) return fail(quoted(token) + " is not a finite double");
        texcoords.push_back(v);
      }
    } else if (keyword == "f") {
      const std::size_t start = refs.size();
      const auto so_far = static_cast<std::int64_t>(out.vertices.size() / 3);
      const auto texcoords_so_far = static_cast<std::int64_t>(texcoords.size() / 2);
      std::string_view token;
      while (tokens.next(token)) {
        std::int64_t i = 0;
        const Parsed parsed = parse_number(token.substr(0, token.find('/')), i);
        if (parsed == Parsed::NotANumber) return fail(quoted(token) + " is not a vertex reference");
        if (parsed == Parsed::OutOfRange) return fail("vertex index " + quoted(token) + " is out of range");
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
        // The texture index: between the first and a second '/', empty or absent if none.
        const std::size_t slash = token.find('/');
        std::string_view t = slash == std::string_view::npos ? std::string_view() : token.substr(slash + 1);
        t = t.substr(0, t.find('/'));
        if (t.empty()) {
          if (missing_line == 0) missing_line = line;
          texture_refs.push_back(0);
          continue;
        }
        std::int64_t ti = 0;
        const Parsed tparsed = parse_number(t, ti);
        if (tparsed == Parsed::NotANumber) return fail(quoted(token) + " is not a vertex reference");
        if (tparsed == Parsed::OutOfRange) return fail("texture index " + quoted(t) + " is out of range");
        if (ti == 0) return fail("texture index 0 (indices count from 1)");
        std::int64_t tindex = 0;
        if (ti > 0) {
          if (ti > kMaxVertices) return fail("texture index " + std::to_string(ti) + " is out of range");
          tindex = ti - 1;
          if (tindex > greatest_texture) {
            greatest_texture = tindex;
            greatest_texture_line = line;
          }
        } else {
          tindex = texcoords_so_far + ti;
          if (tindex < 0 && texture_problem.empty()) {
            texture_problem = "texture index " + std::to_string(ti) + " is out of range (" +
                              std::to_string(texcoords_so_far) + " texture coordinates so far)";
            texture_problem_line = line;
          }
          tindex = std::max<std::int64_t>(tindex, 0);
        }
        texture_refs.push_back(static_cast<std::uint32_t>(tindex));
      }
      if (refs.size() - start < 3) return fail("a face needs at least 3 vertices");
      face_starts.push_back(start);
    }
    // Anything else (vn, vt, o, g, s, l, p, usemtl, mtllib, ...) carries no surface.
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
  // with_uv: a vertex per distinct (position, texture coordinate) pair, in first-use order,
  // when every reference has a texture index; `emitted` maps refs to those vertices.
  std::vector<std::uint32_t> emitted;
  std::vector<double> split_vertices;
  if (with_uv) {
    const auto texture_count = static_cast<std::int64_t>(texcoords.size() / 2);
    if (texture_count > 0 && !texture_problem.empty()) {
      line = texture_problem_line;
      return fail(texture_problem);
    }
    if (texture_count > 0 && greatest_texture >= texture_count) {
      line = greatest_texture_line;
      return fail("texture index " + std::to_string(greatest_texture + 1) + " is out of range (the file has " +
                  std::to_string(texture_count) + " texture coordinates)");
    }
    if (texture_count == 0 || missing_line != 0) {
      out.uv_missing_line = texture_count == 0 ? 0 : missing_line;
    } else {
      std::unordered_map<std::uint64_t, std::uint32_t> vertex_of;  // (position << 32 | texture) -> vertex
      vertex_of.reserve(refs.size());
      emitted.reserve(refs.size());
      for (std::size_t r = 0; r < refs.size(); ++r) {
        const std::uint64_t key = (std::uint64_t{refs[r]} << 32) | texture_refs[r];
        const auto [it, added] = vertex_of.emplace(key, static_cast<std::uint32_t>(split_vertices.size() / 3));
        if (added) {
          if (split_vertices.size() / 3 >= static_cast<std::size_t>(kMaxVertices)) {
            error = "line " + std::to_string(line) + ": too many distinct (vertex, texture) pairs";
            return false;
          }
          const double* p = &out.vertices[3 * std::size_t{refs[r]}];
          split_vertices.insert(split_vertices.end(), p, p + 3);
          out.uv.push_back(texcoords[2 * std::size_t{texture_refs[r]}]);
          out.uv.push_back(texcoords[2 * std::size_t{texture_refs[r]} + 1]);
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
