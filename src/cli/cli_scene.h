/* cli_scene — how the CLI names its files and reads scene decks. Every file
 * argument may be a host path or a CMS fileid ('FIG1 SCENE A'), resolved
 * through the disk map of --disk L=DIR options and MAPRT_DISK_L variables;
 * decks are read through the CMS shim in any form it knows (ASCII lines,
 * EBCDIC cards, V streams, punch decks). */
#ifndef CLI_SCENE_H
#define CLI_SCENE_H
#include "model/scene.h"
#include "vm_cms_shim/cms_disk.h"
#include "vm_cms_shim/cms_recs.h"

typedef struct cli_files {
    cms_disks disks;
    cms_decode_opts decode;      /* --read-as, --cp */
} cli_files;

/* Initialises the disk map from the environment; DIAG_INPUT on a bad
 * MAPRT_DISK_L value (err says which). Release with cli_files_free. */
int cli_files_init(cli_files *f, diag *err);
void cli_files_free(cli_files *f);

/* If argv[*i] is one of the shared file options (--disk L=DIR, --read-as
 * FORM, --cp 037|1047), consumes it and its value and returns 1; a bad value
 * prints a usage error and sets *status to CLI_USAGE. Returns 0 otherwise. */
int cli_files_option(cli_files *f, const char *cmd, int argc, char **argv, int *i, int *status);

/* The help text lines for the shared options. */
extern const char cli_files_help[];

/* Reads and parses the deck `name` (a name such as "fig1" that is neither a
 * host file nor a fileid is a shipped scene, cli_data.h). Images the deck names are read beside
 * it: relative to its host directory, and for a deck read by fileid also as
 * fileid "FN FT m" on its disk for an image written FN.FT. 0 and *out
 * (scene_free it), or a diag status with err naming the file or fileid and
 * record. */
int cli_scene_load(const cli_files *f, const char *name, scene **out, diag *err);
/* cli_scene_load that also gives the SHA-256 of the deck's bytes as read
 * for the parse (64 hex digits), for the picture's provenance: a deck
 * changed while it renders is not checksummed again. */
int cli_scene_load_sum(const cli_files *f, const char *name, scene **out, char sha256[65], diag *err);

/* The SHA-256 of the file `name` (as `sha256sum` prints it) for a
 * picture's provenance. 0, or a diag status. */
int cli_file_sha256(const cli_files *f, const char *name, char hex[65], diag *err);

/* Every name: a host file that exists wins over reading the name as a
 * fileid (a file 'my deck' is not 'MY DECK A1'). */
/* Resolves an output name to a host path: *path (mem_free it). */
int cli_output_path(const cli_files *f, const char *name, char **path, diag *err);
#endif
