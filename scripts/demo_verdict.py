"""The verdict of a run in one line, as the demos print it (summary.json's `verdict`:
docs/theory.md, "Member checks and the verdict")."""


def verdict_line(summary):
    """'deploys: <reason>' or 'DOES NOT DEPLOY: <reason>'; 'no verdict' without one."""
    verdict = (summary or {}).get("verdict")
    if not verdict:
        return "no verdict"
    return ("deploys: " if verdict["deploys"] else "DOES NOT DEPLOY: ") + verdict["reason"]


def print_verdicts(rows):
    """rows: (label, summary) pairs; one line each."""
    print("verdicts:")
    width = max((len(label) for label, _ in rows), default=0)
    for label, summary in rows:
        print(f"  {label:{width}}  {verdict_line(summary)}")
