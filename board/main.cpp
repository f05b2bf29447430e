#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"deepnav: navigation firmware of a deep-sea work-class ROV"};
  app.require_subcommand(1);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
