#!/usr/bin/env bash
# Runs sbt: an installed one if there is one, else the sbt launcher fetched from Maven
# Central by its coordinates with `mvn dependency:get` (no other package source is needed).
# Works in this repository and in any sbt project below it (e.g. examples/dependent-project).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

if command -v sbt >/dev/null 2>&1; then
  exec sbt "$@"
fi

properties=project/build.properties
[ -f "$properties" ] || properties="$here/project/build.properties"
version=$(sed -n 's/^sbt\.version *= *//p' "$properties" | tr -d '[:space:]')
jar="${HOME}/.m2/repository/org/scala-sbt/sbt-launch/${version}/sbt-launch-${version}.jar"
if [ ! -f "$jar" ]; then
  command -v mvn >/dev/null 2>&1 || { echo "sbt: neither sbt nor mvn is installed" >&2; exit 1; }
  echo "sbt: fetching the sbt ${version} launcher with mvn ..." >&2
  mvn -q dependency:get -Dartifact="org.scala-sbt:sbt-launch:${version}" >&2
fi

# Resolve only from the local caches and Maven Central (project/repositories).
exec java -Xms512m -Xmx3g -Xss4m ${JAVA_OPTS:-} \
  -Dsbt.repository.config="$here/project/repositories" \
  -Dsbt.override.build.repos=true \
  -Dsbt.server.forcestart=false \
  -jar "$jar" "$@"
