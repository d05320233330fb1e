<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros1/main.xsl - ROS PSM (ros-version 1) -> file set (a catkin package).

  Reads:   urn:robomda:psm-ros:1 (schemas/psm-ros/1/psm-ros.xsd), from
           xslt/m2m/ros/psm.xsl with ros-version=1.
  Writes:  urn:robomda:fileset:1 (schemas/fileset/1/fileset.xsd), target "ros1":
             include/<pkg>/<Class>.hpp, src/<Class>.cpp, src/<exe>.cpp  per node
             include/<pkg>/<Class>Base.hpp, and include/<pkg>/<Class>Impl.hpp,
             src/<Class>Impl.cpp (mode user) per node without a realizing class
             msg/<Type>.msg          per generated message
             CMakeLists.txt, package.xml
             launch/<model>.launch, launch/<model>_<host>.launch, launch/<model>_<set>.launch
             config/<instance>.yaml
             src/<subsystem>_coordinator.cpp, launch/<model>_<job>_<instance>.launch
                                     per job coordinator (ros1-jobs.xsl)
             test/<model>.test, test/test_<model>_system.py  the system's rostest (ros1-test.xsl)
           One fs:file a line, as f:indent (common/indent.xsl) would indent
           the file set, written so directly (t:indented-content: no copy of
           all the text).
  Params:  model-dir-from-output (xslt/m2t/ros-common/ros-text.xsl).
  Errors:  none (the PSM is complete and valid).
  Modules: ../ros-common/ros-text.xsl, ../common/user-class.xsl,
           ../ros-common/ros-user.xsl, ros1-cpp.xsl, ros1-build.xsl, ros1-launch.xsl,
           ../common/jobs.xsl, ../ros-common/ros-jobs.xsl, ros1-jobs.xsl,
           ../ros-common/ros-test.xsl, ros1-test.xsl.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:t="urn:robomda:xslt:template"
    exclude-result-prefixes="#all">

  <xsl:include href="../../common/indent.xsl"/>
  <xsl:include href="../common/text.xsl"/>
  <xsl:include href="../common/package-manifest.xsl"/>
  <xsl:include href="../common/data-types.xsl"/>
  <xsl:include href="../../common/naming.xsl"/>
  <xsl:include href="../ros-common/ros-text.xsl"/>
  <xsl:include href="../common/user-class.xsl"/>
  <xsl:include href="../ros-common/ros-user.xsl"/>
  <xsl:include href="ros1-cpp.xsl"/>
  <xsl:include href="ros1-build.xsl"/>
  <xsl:include href="ros1-launch.xsl"/>
  <xsl:include href="../common/jobs.xsl"/>
  <xsl:include href="../ros-common/ros-jobs.xsl"/>
  <xsl:include href="ros1-jobs.xsl"/>
  <xsl:include href="../ros-common/ros-test.xsl"/>
  <xsl:include href="ros1-test.xsl"/>

  <xsl:output method="xml" indent="no" encoding="UTF-8" cdata-section-elements="fs:file"/>
  <xsl:mode name="m:emit-files" on-no-match="fail"/>

  <xsl:variable name="fp:cpp-xsl" as="xs:string" select="'m2t/ros1/ros1-cpp.xsl'"/>
  <xsl:variable name="fp:build-xsl" as="xs:string" select="'m2t/ros1/ros1-build.xsl'"/>
  <xsl:variable name="fp:launch-xsl" as="xs:string" select="'m2t/ros1/ros1-launch.xsl'"/>
  <xsl:variable name="fp:jobs-xsl" as="xs:string" select="'m2t/ros1/ros1-jobs.xsl'"/>

  <xsl:template match="r:package" mode="m:emit-files" as="element(fs:files)">
    <xsl:variable name="pkg" as="xs:string" select="@name"/>
    <xsl:variable name="package" as="element(r:package)" select="."/>
    <xsl:variable name="files" as="element(fs:file)*">
      <xsl:for-each select="r:node">
        <xsl:sequence select="fp:file(concat('include/', $pkg, '/', @class, '.hpp'), 'generated', $fp:cpp-xsl, fp:ros1-header(.))"/>
        <xsl:sequence select="fp:file(concat('src/', @class, '.cpp'), 'generated', $fp:cpp-xsl, fp:ros1-source(.))"/>
        <xsl:sequence select="fp:file(concat('src/', @executable, '.cpp'), 'generated', $fp:cpp-xsl, fp:ros1-main(.))"/>
        <!-- no realizing class: <Class>Base and the user's <Class>Impl (ros-user.xsl) -->
        <xsl:sequence select="fp:ros-user-files(.)"/>
      </xsl:for-each>
      <xsl:sequence select="fp:ros-type-files(.)"/>
      <xsl:sequence select="fp:file('CMakeLists.txt', 'generated', $fp:build-xsl, fp:ros1-cmakelists(.))"/>
      <xsl:sequence select="fp:file('package.xml', 'generated', $fp:build-xsl, fp:ros1-package-xml(.))"/>
      <xsl:sequence select="fp:file(fp:ros1-test-paths(.)[1], 'generated', $fp:test-xsl, fp:ros1-test-launch(.)),
                            fp:file(fp:ros1-test-paths(.)[2], 'generated', $fp:test-xsl, fp:ros1-test-node(.))"/>
      <xsl:sequence select="fp:file(concat('launch/', @deploy-name, '.launch'), 'generated', $fp:launch-xsl, fp:ros1-top-launch(.))"/>
      <xsl:for-each select="r:host">
        <xsl:sequence select="fp:file(concat('launch/', $package/@deploy-name, '_', @launch, '.launch'), 'generated', $fp:launch-xsl,
                                      fp:ros1-host-launch($package, .))"/>
      </xsl:for-each>
      <xsl:for-each select="r:set">
        <xsl:sequence select="fp:file(concat('launch/', $package/@deploy-name, '_', @launch, '.launch'), 'generated', $fp:launch-xsl,
                                      fp:ros1-set-launch($package, .))"/>
      </xsl:for-each>
      <xsl:for-each select="r:coordinator">
        <xsl:sequence select="fp:file(concat('src/', @executable, '.cpp'), 'generated', $fp:jobs-xsl, fp:ros1-coordinator(.))"/>
        <xsl:for-each select="fp:ros1-job-starts(.)">
          <xsl:sequence select="fp:file('launch/' || fp:ros1-job-launch-name(.), 'generated', $fp:jobs-xsl, fp:ros1-job-launch(.))"/>
        </xsl:for-each>
      </xsl:for-each>
      <xsl:for-each select="r:instance">
        <xsl:sequence select="fp:file(concat('config/', @name, '.yaml'), 'generated', $fp:launch-xsl, fp:params-yaml(., $fp:launch-xsl))"/>
        <xsl:sequence select="fp:file(concat('config/', @name, '.user.yaml'), 'user', $fp:launch-xsl,
            fp:user-params-yaml(concat('the tuned parameters of instance ', @name), concat('config/', @name, '.yaml'), $fp:launch-xsl, '{}'))"/>
      </xsl:for-each>
    </xsl:variable>
    <fs:files target="ros1">
      <xsl:call-template name="t:indented-content">
        <xsl:with-param name="children" select="$files"/>
        <xsl:with-param name="margin" select="'&#10;'"/>
      </xsl:call-template>
    </fs:files>
  </xsl:template>
</xsl:stylesheet>
