#ifndef hati_base_version_h
#define hati_base_version_h

namespace hati
{
/**
 * The git commit hati was built from (the first 12 hex digits, `-dirty`
 * when the tree had changes), stamped when CMake configures the build
 * (it re-configures when the checkout's HEAD moves), or `unknown` outside
 * a git checkout: `hati --version`, summary.json `git_commit` and the
 * provenance of a report.
 */
const char *hati_git_commit();
} // namespace hati

#endif
