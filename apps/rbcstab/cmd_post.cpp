// rbcstab post: the post-instability state (paper Sec. V): Delta~2 from Eq. ss with the continuous l_* and with
// the integer surviving mode, against the simulated long-time Delta-bar_2; optionally the Fig. 6e table.
#include <iostream>
#include <memory>

#include "checks.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/report/panels.hpp"
#include "rbcstab/sweep/sweep_io.hpp"
#include "rbcstab/verdict/verdict_io.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct PostOptions {
  SceneOptions scene;
  bool json = false;
  bool fig6e = false;
  std::vector<double> fig6e_lambda, fig6e_B, fig6e_C;
  ProgressOutput progress;
};

int run_fig6e(const PostOptions& o) {
  // The scene gives Delta, Delta0, beta, delta, L, T and the integrator (and a [fig6e] table its grid), as a
  // Fig. 6e panel report; the flags choose the grid.
  const SceneFile sf = o.scene.resolve(TruncationUse::grid);
  Fig6eOptions f = fig6e_options(sf);
  if (!o.fig6e_lambda.empty()) f.lambdas = o.fig6e_lambda;
  if (!o.fig6e_B.empty()) f.B = o.fig6e_B;
  if (!o.fig6e_C.empty()) f.C = o.fig6e_C;
  f.on_progress = o.progress.callback("post --fig6e:", "runs");
  const std::vector<Fig6eRow> rows = fig6e_table(f);
  // The CSV is the one a Fig. 6e panel report draws (report/panels.hpp).
  std::cout << (o.json ? fig6e_json(sf, rows).dump(2) + "\n" : fig6e_csv(f, rows));
  return kOk;
}

int run(const PostOptions& o) {
  if (o.fig6e) return run_fig6e(o);
  SceneFile sf = o.scene.read_unchecked();  // run_post checks it
  sf.options.on_progress = o.progress.callback("post: t =", "");
  const PostRun p = run_post(std::move(sf));
  std::cout << (o.json ? post_json(p.file, p.post, p.run).dump(2) + "\n" : post_text(p.file, p.post, p.run));
  return p.run.status == IntegrationStatus::success ? kOk : kRunFailed;
}

Runner add_post(CLI::App& app) {
  auto o = std::make_shared<PostOptions>();
  o->scene.add_to(app);
  app.add_flag("--json", o->json, "print one JSON object on stdout");
  o->progress.add_flags(app);
  app.add_flag("--fig6e", o->fig6e,
               "print the Fig. 6e table instead (Delta~2 vs simulated Delta-bar_2 over lambda, B, C; ~80 runs; Delta, "
               "Delta0, beta, delta, L, T from the scene)");
  app.add_option("--fig6e-lambda", o->fig6e_lambda, "lambda values of the Fig. 6e table, each > 0 (default 1 5)")
      ->check(positive());
  app.add_option("--fig6e-B", o->fig6e_B, "B values of the Fig. 6e table, each > 0 (default 1..10)")->check(positive());
  app.add_option("--fig6e-C", o->fig6e_C, "C values of the Fig. 6e table, each > 0 (default 0.01 0.02 0.04 0.08)")
      ->check(positive());
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterPost{"post", "Post-instability excess area Delta~2: predicted (Eq. ss) vs simulated",
                                    add_post, 31};
}  // namespace

}  // namespace rbcstab::cli
