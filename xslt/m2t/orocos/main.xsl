<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/orocos/main.xsl - Orocos PSM -> file set (the Orocos package text).

  Reads:   urn:robomda:psm-orocos:1 (schemas/psm-orocos/1/psm-orocos.xsd),
           from xslt/m2m/orocos/psm.xsl.
  Writes:  urn:robomda:fileset:1 (schemas/fileset/1/fileset.xsd), target "orocos":
             include/<pkg>/<Class>.hpp, src/<Class>.cpp     per component (generated)
             include/<pkg>/<Class>Base.hpp, src/<Class>Base.cpp + user
             include/<pkg>/<Class>.hpp, src/<Class>.cpp (mode user) when the
             component has no realizing class
             include/<Type>.hpp per data type and enumeration the
             components use, src/typekit.cpp (their RTT typekit)
             src/components.cpp, CMakeLists.txt, package.xml
             deploy/<model>.xml, deploy/<model>.ops, deploy/<model>.lua,
             deploy/<model>-check.lua (several processes: these four per
             process, deploy/<host>_<process>.*, and per host
             deploy/start_<host>.sh, with deploy/start-helper.lua)
             deploy/<instance>.user.cpf (mode user) per instance with
             properties: the user's tuned values, loaded after the model's
           One fs:file a line, as f:indent (common/indent.xsl) would indent
           the file set, each written straight into it (no copy of all the
           text).
  Params:  model-dir-from-output (xslt/m2t/common/text.xsl).
  Errors:  none (the PSM is complete and valid).
  Modules: ../common/text.xsl (the text kit every target shares),
           ../common/package-manifest.xsl, ../common/user-class.xsl (the
           user files, shared with ROS), ../common/data-types.xsl, orocos-cpp.xsl, orocos-build.xsl, orocos-deploy.xsl, orocos-jobs.xsl (job coordinators),
           orocos-types.xsl.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    exclude-result-prefixes="#all">

  <xsl:include href="../common/text.xsl"/>
  <xsl:include href="../common/package-manifest.xsl"/>
  <xsl:include href="../common/user-class.xsl"/>
  <xsl:include href="orocos-cpp.xsl"/>
  <xsl:include href="orocos-build.xsl"/>
  <xsl:include href="orocos-deploy.xsl"/>
  <xsl:include href="orocos-jobs.xsl"/>
  <xsl:include href="orocos-processes.xsl"/>
  <xsl:include href="../common/data-types.xsl"/>
  <xsl:include href="orocos-types.xsl"/>

  <xsl:output method="xml" indent="no" encoding="UTF-8" cdata-section-elements="fs:file"/>

  <!-- the modules that write the files, as each file's banner names them -->
  <xsl:variable name="fp:cpp-xsl" as="xs:string" select="'m2t/orocos/orocos-cpp.xsl'"/>
  <xsl:variable name="fp:build-xsl" as="xs:string" select="'m2t/orocos/orocos-build.xsl'"/>
  <xsl:variable name="fp:deploy-xsl" as="xs:string" select="'m2t/orocos/orocos-deploy.xsl'"/>
  <xsl:variable name="fp:typekit-xsl" as="xs:string" select="'m2t/orocos/orocos-types.xsl'"/>
  <xsl:mode name="m:emit-files" on-no-match="fail"/>
  <!-- what goes before each file in fs:files: one file a line -->
  <xsl:variable name="fp:file-margin" as="xs:string" select="'&#10;  '"/>

  <!-- the file set comes out as f:indent (common/indent.xsl) would indent
       it (one fs:file a line; their text as it is), written so directly:
       f:indent would copy all the text once more -->
  <xsl:template match="/" as="document-node()">
    <xsl:document>
      <xsl:apply-templates select="o:deployment" mode="m:emit-files"/>
    </xsl:document>
  </xsl:template>

  <xsl:template match="o:deployment" mode="m:emit-files" as="element(fs:files)">
    <xsl:variable name="pkg" as="xs:string" select="@package"/>
    <!-- the definitions, once: not a new sequence of them all for each
         type, nor a search of the whole model for them in each component's
         header (a scan per component: quadratic, issue 35) -->
    <xsl:variable name="definitions" as="element()*" select="o:types/(o:struct | o:enum)"/>
    <!-- each file on a line of its own, as f:indent would put it: written
         straight into fs:files, not built first and copied (the text of
         every file would be copied once more) -->
    <fs:files target="orocos">
      <xsl:for-each select="o:task-context">
        <xsl:sequence select="$fp:file-margin, fp:file(concat('include/', $pkg, '/', @generated-class, '.hpp'), 'generated', $fp:cpp-xsl,
                                      if (@kind eq 'thread') then fp:thread-header(.) else fp:cpp-header(., $definitions))"/>
        <xsl:sequence select="$fp:file-margin, fp:file(concat('src/', @generated-class, '.cpp'), 'generated', $fp:cpp-xsl,
                                      if (@kind eq 'thread') then fp:thread-source(.) else fp:cpp-source(.))"/>
        <xsl:if test="@kind eq 'base'">
          <xsl:sequence select="$fp:file-margin, fp:user-file(concat('include/', $pkg, '/', @class, '.hpp'), ., fp:user-header(.))"/>
          <xsl:sequence select="$fp:file-margin, fp:user-file(concat('src/', @class, '.cpp'), ., fp:user-source(.))"/>
        </xsl:if>
      </xsl:for-each>
      <xsl:for-each select="$definitions">
        <xsl:sequence select="$fp:file-margin, fp:file('include/' || @header, 'generated', 'm2t/common/data-types.xsl',
                                      fp:type-header(., $definitions, ../../@model-name))"/>
      </xsl:for-each>
      <xsl:sequence select="o:types ! ($fp:file-margin, fp:file('src/typekit.cpp', 'generated', $fp:typekit-xsl, fp:typekit-cpp(.)))"/>
      <xsl:sequence select="$fp:file-margin, fp:file('src/components.cpp', 'generated', $fp:cpp-xsl, fp:components-cpp(.))"/>
      <xsl:sequence select="$fp:file-margin, fp:file('CMakeLists.txt', 'generated', $fp:build-xsl, fp:cmakelists(.))"/>
      <xsl:sequence select="$fp:file-margin, fp:file('package.xml', 'generated', $fp:build-xsl, fp:package-xml(.))"/>
      <!-- one deployment per process (orocos-processes.xsl) -->
      <xsl:variable name="deployment" as="element(o:deployment)" select="."/>
      <xsl:for-each select="o:process">
        <xsl:variable name="view" as="element(o:deployment)" select="fp:process-view($deployment, .)"/>
        <xsl:sequence select="$fp:file-margin, fp:file(concat('deploy/', @file, '.xml'), 'generated', $fp:deploy-xsl, fp:deploy-xml($view))"/>
        <xsl:sequence select="$fp:file-margin, fp:file(concat('deploy/', @file, '.ops'), 'generated', $fp:deploy-xsl, fp:deploy-ops($view))"/>
        <xsl:sequence select="$fp:file-margin, fp:file(concat('deploy/', @file, '.lua'), 'generated', $fp:deploy-xsl, fp:deploy-lua($view))"/>
        <xsl:sequence select="$fp:file-margin, fp:file(concat('deploy/', @file, '-check.lua'), 'generated', $fp:deploy-xsl, fp:deploy-check-lua($view, $deployment))"/>
      </xsl:for-each>
      <!-- the job coordinators' programs (orocos-jobs.xsl, docs/jobs.md) -->
      <xsl:for-each select="o:coordinator">
        <xsl:sequence select="$fp:file-margin, fp:file('deploy/' || @script, 'generated', $fp:jobs-xsl, fp:coordinator-lua(., $deployment))"/>
      </xsl:for-each>
      <!-- several processes: a start script per host -->
      <xsl:if test="count(o:process) gt 1">
        <xsl:sequence select="$fp:file-margin, fp:file('deploy/start-helper.lua', 'generated', $fp:deploy-xsl, fp:start-helper(.))"/>
        <xsl:for-each-group select="o:process" group-by="string(@host)">
          <xsl:variable name="host" as="element(o:host)?" select="fp:in-process('fp:host-named', $deployment, current-grouping-key())"/>
          <xsl:sequence select="$fp:file-margin, fp:file('deploy/' || current-group()[1]/@start-script, 'generated', $fp:deploy-xsl,
                                        fp:start-script($deployment, $host, current-group()))"/>
        </xsl:for-each-group>
      </xsl:if>
      <xsl:for-each select="o:instance[o:property-value]">
        <xsl:sequence select="$fp:file-margin, fp:user-cpf-file(.)"/>
      </xsl:for-each>
      <xsl:text>&#10;</xsl:text>
    </fs:files>
  </xsl:template>

  <!-- a user file of task context $tc: what it implements and what the
       generated base class requires of it (ports, operations, hooks) -->
  <xsl:function name="fp:user-file" as="element(fs:file)">
    <xsl:param name="path" as="xs:string"/>
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:param name="text" as="xs:string"/>
    <xsl:sequence select="fp:user-class-file($path, $fp:cpp-xsl, $tc, (
        $tc/o:port ! concat('port ', @name, ' ', @direction, ' ', @cpp-type),
        $tc/o:operation ! concat('operation ', @name, '(', string-join(o:parameter/@decl-type, ', '), ') ', @return-type),
        $tc/o:hook[@call] ! concat('hook ', @name)), $text)"/>
  </xsl:function>

  <!-- the user's tuned property values of instance $i: what it implements
       is the instance, its signature the properties it may set -->
  <xsl:function name="fp:user-cpf-file" as="element(fs:file)">
    <xsl:param name="instance" as="element(o:instance)"/>
    <fs:file path="deploy/{fp:user-cpf($instance)}" mode="user" stylesheet="{$fp:deploy-xsl}" implements="{$instance/@xmi-id}"
             implements-name="{$instance/@name}"
             signature="{string-join($instance/o:property-value ! concat('property ', @name, ' ', @xml-type), '; ')}"
             shape="{fp:user-cpf-shape($instance)}">
      <xsl:value-of select="fp:user-cpf-text($instance)"/>
    </fs:file>
  </xsl:function>

  <!-- what the writer checks a user's .cpf against, as deep as the types
       go (OUT005, src/robomda/output.py): "path type" for each property and
       each member or element below it ("gains.stiffness double",
       "desired[] double", "stages[].damping double"), "; "-separated -->
  <xsl:function name="fp:user-cpf-shape" as="xs:string">
    <xsl:param name="instance" as="element(o:instance)"/>
    <xsl:sequence select="string-join(sort(distinct-values($instance/o:property-value !
        (if (o:value) then (for $v in o:value/descendant-or-self::o:value
                            return concat(@name, replace($v/@path, '\[[0-9]+\]', '[]'), ' ', $v/@xml-type))
         else concat(@name, ' ', @xml-type)))), '; ')"/>
  </xsl:function>
</xsl:stylesheet>
