#include "hard_cases/hard_case_support.h"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>

#include "shpack/conventions.h"

extern char** environ;

namespace shpack_hard {

namespace fs = std::filesystem;

const RuleLd& gauss_legendre_ld(int q) {
  static std::map<int, RuleLd> cache;  // the tests are single-threaded
  if (const auto it = cache.find(q); it != cache.end()) return it->second;
  const long double pi = std::numbers::pi_v<long double>;
  RuleLd rule;
  for (int k = 0; k < q; ++k) {
    // Newton's iteration on P_q from the classical first guess cos(pi (k + 3/4) / (q + 1/2)).
    long double x = std::cos(pi * (k + 0.75L) / (q + 0.5L)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      long double p0 = 1, p1 = x;  // P_0, P_1
      for (int l = 2; l <= q; ++l) {
        const long double p2 = ((2 * l - 1) * x * p1 - (l - 1) * p0) / l;
        p0 = p1;
        p1 = p2;
      }
      // p1 = P_q(x), p0 = P_(q-1)(x); P_q' = q (x P_q - P_(q-1)) / (x^2 - 1).
      dp = q == 1 ? 1.0L : q * (x * p1 - p0) / (x * x - 1);
      const long double step = p1 / dp;
      x -= step;
      if (std::fabs(step) < 1e-22L) break;
    }
    rule.x.push_back(x);
    rule.w.push_back(2 / ((1 - x * x) * dp * dp));
  }
  return cache.emplace(q, std::move(rule)).first->second;
}

int order_ld(long double length, long double nu) {
  const long double ln = length * nu;
  if (!(ln > 0)) return 1;
  for (int q = 1; q < 48; ++q) {
    const long double log_r = 2 * q * std::log(ln) + 4 * std::lgamma(q + 1.0L) - std::log(2 * q + 1.0L) -
                              3 * std::lgamma(2 * q + 1.0L);
    if (log_r <= std::log(1e-22L)) return q;
  }
  return 48;
}

namespace {

// int_a^b f(t) dt by the rule of order q in long double.
template <class F>
long double integrate_ld(long double a, long double b, int q, F f) {
  const RuleLd& r = gauss_legendre_ld(q);
  const long double mid = (a + b) / 2, half = (b - a) / 2;
  long double sum = 0;
  for (std::size_t k = 0; k < r.x.size(); ++k) sum += r.w[k] * f(mid + half * r.x[k]);
  return half * sum;
}

struct BasisScalesLd {
  long double k0, k1, k2, k3, k4;
};
BasisScalesLd basis_scales_ld() {
  const long double root_pi = std::sqrt(std::numbers::pi_v<long double>);
  return {1.0L / (2.0L * root_pi),              // 1/(2 sqrt(pi))
          std::sqrt(3.0L) / (2.0L * root_pi),   // sqrt(3)/(2 sqrt(pi))
          std::sqrt(15.0L) / (2.0L * root_pi),  // sqrt(15)/(2 sqrt(pi))
          std::sqrt(5.0L) / (4.0L * root_pi),   // sqrt(5)/(4 sqrt(pi))
          std::sqrt(15.0L) / (4.0L * root_pi)};  // sqrt(15)/(4 sqrt(pi))
}

}  // namespace

std::array<long double, 9> basis_long_double(long double x, long double y, long double z) {
  const BasisScalesLd k = basis_scales_ld();
  return {k.k0,         k.k1 * y,     k.k1 * z, k.k1 * x, k.k2 * x * y, k.k2 * y * z, k.k3 * (3 * z * z - 1),
          k.k2 * x * z, k.k4 * (x * x - y * y)};
}

EquirectOracle::EquirectOracle(std::uint32_t width, std::uint32_t height) : width_(width), height_(height) {
  const long double pi = std::numbers::pi_v<long double>;
  const int qt = order_ld(pi / height, 3), ql = order_ld(2 * pi / width, 2);
  // Rows of the southern half are the mirror images (theta -> pi - theta) of northern rows,
  // integrated near theta = 0 where theta is accurate relative to its size: the integrals
  // odd in cos theta change sign, the others are equal. (Integrating near theta = pi would
  // lose u pi / theta of relative accuracy in sin theta: 2^-64 * 2H at the south pole row.)
  rows_.resize(height);
  for (std::uint32_t j = 0; j < height - j; ++j) {
    const long double t0 = pi * j / height, t1 = pi * (j + 1.0L) / height;
    auto in = [&](auto f) { return integrate_ld(t0, t1, qt, f); };
    rows_[j] = {in([](long double t) { return std::sin(t); }),
                in([](long double t) { return std::cos(t) * std::sin(t); }),
                in([](long double t) { return std::sin(t) * std::sin(t); }),
                in([](long double t) { return std::sin(t) * std::sin(t) * std::cos(t); }),
                in([](long double t) { return std::sin(t) * std::sin(t) * std::sin(t); }),
                in([](long double t) { return std::cos(t) * std::cos(t) * std::sin(t); })};
    const Row& r = rows_[j];
    if (height - 1 - j != j) rows_[height - 1 - j] = {r.t1, -r.tc, r.ts, -r.tsc, r.ts3, r.tc2};
  }
  for (std::uint32_t i = 0; i < width; ++i) {
    const long double l0 = (0.5L - (i + 1.0L) / width) * 2 * pi, l1 = (0.5L - static_cast<long double>(i) / width) * 2 * pi;
    auto in = [&](auto f) { return integrate_ld(l0, l1, ql, f); };
    columns_.push_back({l1 - l0, in([](long double l) { return std::cos(l); }),
                        in([](long double l) { return std::sin(l); }),
                        in([](long double l) { return std::cos(l) * std::cos(l); }),
                        in([](long double l) { return std::sin(l) * std::sin(l); }),
                        in([](long double l) { return std::sin(l) * std::cos(l); })});
  }
}

std::array<long double, 10> EquirectOracle::texel(std::uint32_t i, std::uint32_t j) const {
  const Row& r = rows_[j];
  const Column& c = columns_[i];
  const BasisScalesLd k = basis_scales_ld();
  return {k.k0 * r.t1 * c.l1,
          k.k1 * r.tc * c.l1,                            // y = cos theta
          k.k1 * r.ts * c.ls,                            // z = sin theta sin lon
          k.k1 * r.ts * c.lc,                            // x = sin theta cos lon
          k.k2 * r.tsc * c.lc,                           // xy
          k.k2 * r.tsc * c.ls,                           // yz
          k.k3 * (3 * r.ts3 * c.lss - r.t1 * c.l1),      // 3 z^2 - 1
          k.k2 * r.ts3 * c.lsc,                          // xz
          k.k4 * (r.ts3 * c.lcc - r.tc2 * c.l1),         // x^2 - y^2
          r.t1 * c.l1};
}

ShLd EquirectOracle::project(const std::vector<float>& rgb) const {
  // Each row in long double, then the rows: error <= (W + H) 2^-64 sum |terms|.
  ShLd total{};
  for (std::uint32_t j = 0; j < height_; ++j) {
    ShLd row{};
    for (std::uint32_t i = 0; i < width_; ++i) {
      const float* v = rgb.data() + (std::size_t{j} * width_ + i) * 3;
      if (v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f) continue;
      const std::array<long double, 10> t = texel(i, j);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 9; ++k) row[c][k] += static_cast<long double>(v[c]) * t[k];
    }
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 9; ++k) total[c][k] += row[c][k];
  }
  return total;
}

std::array<long double, 10> cube_texel_oracle(std::uint32_t n, int face, std::uint32_t x, std::uint32_t y) {
  const shpack::CubeFaceAxes& f = shpack::kCubeFaceAxes[static_cast<std::size_t>(face)];
  const RuleLd& rule = gauss_legendre_ld(12);
  const long double a0 = 2.0L * x / n - 1, a1 = 2.0L * (x + 1.0L) / n - 1;
  const long double b0 = 2.0L * y / n - 1, b1 = 2.0L * (y + 1.0L) / n - 1;
  const int sub = std::max(1, static_cast<int>(std::ceil(static_cast<double>(a1 - a0) * 8.0 - 1e-9)));
  const long double ha = (a1 - a0) / sub, hb = (b1 - b0) / sub;
  std::array<long double, 10> sum{};
  for (int sa = 0; sa < sub; ++sa) {
    for (int sb = 0; sb < sub; ++sb) {
      const long double ca = a0 + (sa + 0.5L) * ha, cb = b0 + (sb + 0.5L) * hb;
      for (std::size_t i = 0; i < rule.x.size(); ++i) {
        for (std::size_t j = 0; j < rule.x.size(); ++j) {
          const long double a = ca + ha / 2 * rule.x[i], b = cb + hb / 2 * rule.x[j];
          const long double r2 = 1 + a * a + b * b, r = std::sqrt(r2);
          const long double weight = ha * hb / 4 * rule.w[i] * rule.w[j] / (r2 * r);
          const long double px = f.normal.x + a * f.u_axis.x + b * f.v_axis.x;
          const long double py = f.normal.y + a * f.u_axis.y + b * f.v_axis.y;
          const long double pz = f.normal.z + a * f.u_axis.z + b * f.v_axis.z;
          const std::array<long double, 9> basis = basis_long_double(px / r, py / r, pz / r);
          for (int k = 0; k < 9; ++k) sum[k] += weight * basis[k];
          sum[9] += weight;
        }
      }
    }
  }
  return sum;
}

fs::path shpack_cli() { return SHPACK_CLI_PATH; }

ChildRun run_child(const fs::path& program, const std::vector<std::string>& args, const fs::path& scratch) {
  ChildRun run;
  const fs::path out_file = scratch / "child_stdout.txt", err_file = scratch / "child_stderr.txt";
  std::vector<std::string> argv_text = {program.string()};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    run.err = std::string("posix_spawn failed: ") + std::strerror(spawned);
    return run;
  }
  // Peak RSS: the child's VmHWM (/proc/PID/status), polled every 2 ms until it exits. Not
  // getrusage's ru_maxrss: Linux folds into it the high-water mark of the memory the child
  // had before exec, i.e. this (large) test process's at the time of the spawn.
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {
      run.err = std::string("waitpid failed: ") + std::strerror(errno);
      return run;
    }
    std::ifstream proc("/proc/" + std::to_string(pid) + "/status");
    for (std::string line; std::getline(proc, line);)
      if (line.rfind("VmHWM:", 0) == 0) run.max_rss_kib = std::max(run.max_rss_kib, std::stol(line.substr(6)));
    usleep(2000);
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = read_text(out_file);
  run.err = read_text(err_file);
  std::error_code ignored;
  fs::remove(out_file, ignored);
  fs::remove(err_file, ignored);
  return run;
}

ScratchDir::ScratchDir(const std::string& name)
    : path_(fs::temp_directory_path() / ("shpack_hard_" + name + "_" + std::to_string(::getpid()))) {
  fs::remove_all(path_);
  fs::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;  // a leftover folder is harmless; a destructor cannot fail a test
  fs::remove_all(path_, ignored);
}

std::string write_exr(const fs::path& path, std::uint32_t width, std::uint32_t height, int channels,
                      const std::vector<float>& pixels, FileType type) {
  if (pixels.size() != std::size_t{width} * height * static_cast<std::size_t>(channels))
    return "write_exr: pixel count does not match the size";
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) return "cannot create " + path.string() + ": " + OIIO::geterror();
  OIIO::ImageSpec spec(static_cast<int>(width), static_cast<int>(height), channels,
                       type == FileType::Float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF);
  spec.attribute("compression", "zip");
  if (!out->open(path.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close())
    return path.string() + ": " + out->geterror();
  return {};
}

void write_pfm(const fs::path& path, std::uint32_t width, std::uint32_t height, const std::vector<float>& rgb) {
  std::string bytes = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
  for (std::uint32_t file_row = 0; file_row < height; ++file_row) {
    const std::uint32_t y = height - 1 - file_row;  // PFM: bottom row first
    const char* row = reinterpret_cast<const char*>(rgb.data() + std::size_t{3} * width * y);
    bytes.append(row, std::size_t{3} * width * sizeof(float));  // x86-64: little-endian floats
  }
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace shpack_hard
