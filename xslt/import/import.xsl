<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/import.xsl - entry point of the XMI import: UML 2.x XMI -> PIM.

  Reads:   UML 2.x XMI as UML tools export it (global context item: the XMI
           document): xmi:XMI-wrapped or bare uml:Model / uml:Package; XMI
           2.0, 2.1 (http://schema.omg.org/spec/XMI/2.1), 2.4.x and 2.5.x
           (http://www.omg.org/spec/XMI/YYYYMMDD); UML namespaces of Eclipse
           UML2, OMG and Enterprise Architect, matched by pattern.
           Dialects: Papyrus / Eclipse UML2 / Modelio / RobotML
           (dialect-eclipse.xsl), Enterprise Architect (dialect-ea.xsl),
           MagicDraw / Cameo (dialect-magicdraw.xsl), StarUML and Visual
           Paradigm (dialect-other.xsl).
  Writes:  a PIM valid against schemas/pim/1/pim.xsd (urn:robomda:pim:1):
           application (application.xsl; with the deployment-sequence
           dependencies, pim:dependency), platform (platform.xsl),
           stereotypes and comments (stereotypes.xsl), jobs and
           subsystems (jobs.xsl: pim:coordination, docs/jobs.md). Deterministic and
           engine-independent: no generate-id(), no clock; ids missing in
           the XMI become "robomda.<path>" (xmi-common.xsl, fp:id).
  Params:  source-name (xs:string, default ''): the XMI file's name without
           directories; written to pim:model/@source.
           model-path (xs:string, default ''): space-separated folder URIs
           that referenced model files may be read from besides the model's
           own folder, project and workspace (files.xsl: models split over
           several files; the project is found from the files that mark one,
           so no parameter gives it).
  Modules: xmi-common.xsl (normalisation, keys, references, types),
           files.xsl (models split over several files, the sandbox:
           IMP040, IMP041, IMP049, IMP050),
           urdf.xsl (the kinematic chains of robot Devices, counted in
           the URDF files their Robot stereotype names: IMP040,
           IMP042-IMP048),
           check.xsl (dangling references), application.xsl,
           connector-ends.xsl (nested connector ends), platform.xsl,
           jobs.xsl (jobs and subsystems),
           stereotypes.xsl, dialect-*.xsl (the tools' XMI quirks),
           dialects.xsl (the tools' own profiles: components drawn as
           classes, IMP120-IMP125), ../common/profile.xsl (the robomda
           profile URI); data: ../common/primitive-types.xml,
           dialects.xml.

  Errors (namespace urn:robomda:error, raised with f:fail; the description
  is "CODE: message [xmi:id=ID]", ID being the offending element's xmi:id):
    IMP001  unsupported: XMI 1.x (root XMI with xmi.version / XMI.content).
    IMP002  unsupported: not UML XMI (the root is neither xmi:XMI nor a UML
            Model / Package, or no UML 2.x namespace is used).
    IMP003  unsupported: an xmi:XMI document without a uml:Model or
            uml:Package.
    IMP004  duplicate xmi:id within one file (outside xmi:Extension
            blocks; ids are per file: files.xsl); ID is the duplicated id.
    IMP010  a Property or Parameter whose type is an id not in the file.
    IMP011  a Port whose type (its interface or class) is not in the file.
    IMP012  a Generalization whose general is not in the file.
    IMP013  a ComponentRealization / Realization whose realizingClassifier,
            client or supplier is not in the file.
    IMP014  an InterfaceRealization whose client, supplier or contract is
            not in the file.
    IMP015  a Usage whose client or supplier is not in the file.
    IMP016  a Deployment whose client (location), supplier or
            deployedArtifact is not in the file.
    IMP017  a Manifestation whose client, supplier or utilizedElement is not
            in the file.
    IMP018  a connector end whose role or partWithPort is not in the file.
    IMP019  a CommunicationPath whose memberEnd is not in the file.
    IMP020  a deployment-sequence Dependency (stereotype StartAfter, or
            named startAfter) whose client or supplier is not in the file.
    IMP021  a Generalization that makes its classifier a specialization of
            itself (a cycle of generalizations).
  For IMP010-IMP021 ID is the referencing element's xmi:id and the message
  names the element, its owner, the property and the missing id. An href to
  another file (a library type, an imported model) is never dangling.
    IMP040  (also) a Robot's URDF file outside the model's folder and the
            model path, or a URI of another scheme (urdf.xsl).
    IMP042  a Robot's URDF file that is not there or cannot be read.
    IMP043  a Robot's URDF file that is not well-formed XML.
    IMP044  a Robot's URDF file that is not a URDF robot (root element not
            robot, or unexpanded xacro).
    IMP045  a Robot's rootLink / tipLink that names no link of the file.
    IMP046  a Robot's tipLink that is not below its rootLink.
    IMP047  a joint of a Robot's chain that robomda does not count
            (floating, planar, or no URDF joint type).
  For IMP040-IMP047 about a URDF file ID is the Robot stereotype
  application's xmi:id; they are checked after the references, every one
  of the model reported (f:fail-all).
  Warnings (f:warn) about what the import leaves out: IMP030, IMP101-IMP103
  (application.xsl), IMP110-IMP116 (report.xsl), IMP048 (urdf.xsl: a
  Robot's rootLink / tipLink without urdf), IMP117 (platform.xsl: a
  deployment owned by a node whose client is another), IMP041 and IMP049
  (files.xsl: a model file that is not there, references into a MagicDraw
  used project), IMP120-IMP125 (dialects.xsl: what a tool's own profile
  says that robomda reads differently or not at all); docs/errors.md. Every
  duplicate id and dangling reference is reported (f:fail-all).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:tp="urn:robomda:xslt:template:private"
    xmlns:u="urn:robomda:import:uml"
    xmlns:x="urn:robomda:import:xmi"
    xmlns:pim="urn:robomda:pim:1"
    exclude-result-prefixes="#all">

  <xsl:include href="../common/errors.xsl"/>
  <xsl:include href="../common/indent.xsl"/>
  <xsl:include href="../common/profile.xsl"/>
  <xsl:include href="xmi-common.xsl"/>
  <xsl:include href="files.xsl"/>
  <xsl:include href="urdf.xsl"/>
  <xsl:include href="check.xsl"/>
  <xsl:include href="stereotypes.xsl"/>
  <xsl:include href="dialects.xsl"/>
  <xsl:include href="stand-ins.xsl"/>
  <xsl:include href="application.xsl"/>
  <xsl:include href="connector-ends.xsl"/>
  <xsl:include href="platform.xsl"/>
  <xsl:include href="jobs.xsl"/>
  <xsl:include href="report.xsl"/>
  <xsl:include href="dialect-eclipse.xsl"/>
  <xsl:include href="dialect-ea.xsl"/>
  <xsl:include href="dialect-magicdraw.xsl"/>
  <xsl:include href="dialect-other.xsl"/>

  <xsl:output method="xml" indent="no" encoding="UTF-8"/>
  <xsl:global-context-item as="document-node()" use="optional"/>
  <xsl:mode on-no-match="fail"/>

  <xsl:param name="source-name" as="xs:string" select="''">
    <!-- the XMI file's name without directories; goes to pim:model/@source -->
  </xsl:param>
  <xsl:param name="model-path" as="xs:string" select="''">
    <!-- folders (URIs, space-separated) beside the model's own that model
         files it references may be read from (files.xsl) -->
  </xsl:param>

  <!-- $doc normalised (mode mp:normalise of xmi-common.xsl) -->
  <xsl:function name="fp:normalised" as="document-node()">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:document>
      <xsl:apply-templates select="$doc/*" mode="mp:normalise"/>
    </xsl:document>
  </xsl:function>

  <!-- ====================================================== entry -->
  <!-- Everything derives from the initial match item, not from global
       variables: the Python driver supplies the XMI as the initial match
       selection only, fn:transform (xslt/util/run-pipeline.xsl) as both. -->
  <xsl:template match="/" as="document-node()?">
    <xsl:variable name="src-root" as="element()" select="*"/>
    <xsl:variable name="src-model" as="element()?" select="fp:src-model($src-root)"/>
    <xsl:if test="fp:check-format($src-root, $src-model)">
      <!-- the model files this one references (files.xsl), each once -->
      <xsl:variable name="sandbox" as="map(*)?"
          select="if (base-uri(.) = '') then () else fp:sandbox(., $model-path)"/>
      <xsl:variable name="linked" as="xs:string*"
          select="if (empty($sandbox)) then () else fp:linked-files(., $sandbox)"/>
      <!-- the normalised copy every rule reads (see xmi-common.xsl), with
           the linked files merged in -->
      <xsl:variable name="main-norm" as="document-node()">
        <xsl:document>
          <xsl:apply-templates select="$src-root" mode="mp:normalise"/>
        </xsl:document>
      </xsl:variable>
      <!-- and the library services it names stood in (stand-ins.xsl) -->
      <xsl:variable name="norm" as="document-node()"
          select="fp:with-stand-ins(if (empty($linked)) then $main-norm
                  else fp:merged($main-norm, $linked ! fp:normalised(doc(.)), (string(base-uri(.)), $linked), $sandbox))"/>
      <xsl:variable name="model-el" as="element()" select="fp:model-el($norm)"/>
      <xsl:variable name="root" as="element()" select="fp:model-root($model-el)"/>
      <xsl:if test="fp:check-model($norm, $model-el)">
        <!-- the kinematic chains the robot Devices name in URDF files
             (urdf.xsl), read once: checked here, written by platform.xsl -->
        <xsl:variable name="chains" as="map(*)*"
            select="fp:urdf-chains($root, string(base-uri(.)), $sandbox)"/>
        <xsl:sequence select="fp:check-urdf($chains)"/>
        <xsl:sequence select="fp:used-project-warnings($norm)"/>
        <xsl:variable name="href-types" as="map(*)" select="fp:href-types($norm)"/>
        <xsl:variable name="pim" as="document-node()">
        <xsl:document>
          <pim:model id="{fp:id($root)}" name="{$root/@name}" source="{$source-name}"
              tool="{fp:tool(., $src-model)}" xmi-version="{fp:xmi-version($src-root, $src-model)}"
              uml-namespace="{namespace-uri($src-model)}">
            <xsl:call-template name="tp:decoration">
              <xsl:with-param name="e" select="$root"/>
            </xsl:call-template>
            <pim:application>
              <!-- the system the model names as its top (a Papyrus-RT model's
                   top capsule: dialects.xsl) -->
              <xsl:for-each select="$src-model ! fp:top-name(.)">
                <xsl:attribute name="top" select="."/>
              </xsl:for-each>
              <xsl:apply-templates select="fp:owned-packageables($root)" mode="mp:packageable">
                <xsl:with-param name="href-types" as="map(*)" select="$href-types" tunnel="yes"/>
                <xsl:with-param name="root" as="element()" select="$root" tunnel="yes"/>
              </xsl:apply-templates>
            </pim:application>
            <xsl:call-template name="tp:platform">
              <xsl:with-param name="root" as="element()" select="$root" tunnel="yes"/>
              <xsl:with-param name="href-types" as="map(*)" select="$href-types" tunnel="yes"/>
              <xsl:with-param name="chains" as="map(*)" tunnel="yes"
                  select="map:merge($chains ! map:entry(?device, ?items[. instance of element()]))"/>
            </xsl:call-template>
            <!-- jobs and subsystems (jobs.xsl, docs/jobs.md) -->
            <xsl:call-template name="tp:coordination">
              <xsl:with-param name="root" as="element()" select="$root" tunnel="yes"/>
            </xsl:call-template>
          </pim:model>
        </xsl:document>
        </xsl:variable>
        <xsl:sequence select="fp:report($norm, $pim, $root)"/>
        <xsl:sequence select="f:indent($pim)"/>
      </xsl:if>
    </xsl:if>
  </xsl:template>

  <!-- the UML model element of the original document -->
  <xsl:function name="fp:src-model" as="element()?">
    <xsl:param name="src-root" as="element()"/>
    <xsl:sequence select="
        if (fp:is-uml-ns(namespace-uri($src-root))
            and local-name($src-root) = ('Model', 'Package', 'Profile')) then $src-root
        else if (fp:is-xmi-ns(namespace-uri($src-root)) and local-name($src-root) eq 'XMI')
          then ($src-root/*[fp:is-uml-ns(namespace-uri())][local-name() eq 'Model'],
                $src-root/*[fp:is-uml-ns(namespace-uri())][local-name() eq 'Package'],
                $src-root/*[fp:is-uml-ns(namespace-uri())][local-name() eq 'Profile'])[1]
        else ()"/>
  </xsl:function>

  <!-- format checks (IMP001-IMP003); true when the input is UML 2.x XMI -->
  <xsl:function name="fp:check-format" as="xs:boolean">
    <xsl:param name="src-root" as="element()"/>
    <xsl:param name="src-model" as="element()?"/>
    <xsl:variable name="version-attr" as="attribute()?"
        select="$src-root/@*[local-name() = ('xmi.version', 'version')][not(fp:is-xmi-ns(namespace-uri()))][1]"/>
    <xsl:choose>
      <xsl:when test="local-name($src-root) eq 'XMI'
                      and (exists($src-root/@*[local-name() eq 'xmi.version'])
                           or exists($src-root/*[local-name() eq 'XMI.content'])
                           or not(fp:is-xmi-ns(namespace-uri($src-root))))">
        <xsl:sequence select="f:fail('IMP001', '',
            'unsupported: XMI 1.x (xmi.version=' || ($version-attr, '?')[1] ||
            '); export the model as XMI 2.x / UML 2.x')"/>
      </xsl:when>
      <xsl:when test="empty($src-model)
                      and not(fp:is-xmi-ns(namespace-uri($src-root)) and local-name($src-root) eq 'XMI')">
        <xsl:sequence select="f:fail('IMP002', '',
            'unsupported: not UML XMI (root element ' || name($src-root) ||
            (if (namespace-uri($src-root)) then ' in namespace ' || namespace-uri($src-root) else '') ||
            '); expected xmi:XMI or uml:Model of a UML 2.x namespace')"/>
      </xsl:when>
      <xsl:when test="empty($src-model)">
        <xsl:sequence select="f:fail('IMP003', '',
            'unsupported: the xmi:XMI document holds no uml:Model or uml:Package of a UML 2.x namespace'
            || ' (namespaces: ' || string-join(distinct-values($src-root/*/namespace-uri()), ', ') || ')')"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="true()"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- model checks: duplicate ids (IMP004: every one), else every
       dangling reference in document order (IMP010-IMP021, check.xsl);
       the first is raised, the others reported before it (f:fail-all) -->
  <xsl:function name="fp:check-model" as="xs:boolean">
    <xsl:param name="norm" as="document-node()"/>
    <xsl:param name="model-el" as="element()"/>
    <!-- ids are per file: fp:id is "FILE#id" where several files use one
         (x:qid beside x:id); written out here, not a call per element -->
    <xsl:variable name="ids" as="xs:string*" select="$norm//@x:id ! string((../@x:qid, .)[1])"/>
    <xsl:variable name="duplicates" as="xs:string*">
      <xsl:for-each-group select="if (count(distinct-values($ids)) eq count($ids)) then () else $ids"
          group-by="string(.)">
        <xsl:if test="count(current-group()) gt 1">
          <xsl:sequence select="current-grouping-key()"/>
        </xsl:if>
      </xsl:for-each-group>
    </xsl:variable>
    <xsl:variable name="checked" as="element()*"
        select="$model-el/descendant-or-self::*[map:contains($checked-references, string(@x:type))]"/>
    <!-- when no checked reference dangles, only a Generalization can have
         a problem (a cycle) -->
    <xsl:variable name="problems" as="map(*)*"
        select="(if (exists(fp:any-dangling-ids($checked))) then $checked
                 else $checked[@x:type eq 'Generalization']) ! fp:problems(.)"/>
    <xsl:choose>
      <xsl:when test="exists($duplicates)">
        <xsl:sequence select="f:fail-all($duplicates ! map {
            'code': 'IMP004', 'id': .,
            'message': let $holders := key('fp:by-id', ., $norm) return
                'duplicate xmi:id ''' || . || ''' on ' || count($holders) || ' elements: '
                || string-join($holders ! fp:label(.), ', ') })"/>
      </xsl:when>
      <xsl:when test="exists($problems)">
        <xsl:sequence select="f:fail-all($problems)"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="true()"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- ============================================= tool and versions -->
  <xsl:function name="fp:exporter" as="xs:string">
    <xsl:param name="src-root" as="element()"/>
    <xsl:variable name="doc" as="element()*"
        select="$src-root/*[local-name() eq 'Documentation'][fp:is-xmi-ns(namespace-uri())]"/>
    <xsl:sequence select="normalize-space(string-join(
        ($doc/@*[local-name() = ('exporter', 'Exporter')], $doc/*[local-name() = ('exporter', 'Exporter')]), ' '))"/>
  </xsl:function>

  <xsl:function name="fp:tool" as="xs:string">
    <xsl:param name="src" as="document-node()"/>
    <xsl:param name="src-model" as="element()"/>
    <xsl:variable name="exporter" as="xs:string" select="fp:exporter($src/*)"/>
    <!-- without an exporter the ids tell EA and StarUML: one scan of them
         for both (a second only when one looks like a StarUML id) -->
    <xsl:variable name="marked-id" as="xs:string?" select="if ($exporter) then () else fp:marked-id($src)"/>
    <xsl:sequence select="
        if (fp:is-ea($src, $exporter, $marked-id)) then 'enterprise-architect'
        else if (fp:is-magicdraw($src, $exporter)) then 'magicdraw'
        else if (fp:is-staruml($src, $exporter, $marked-id)) then 'staruml'
        else if (fp:is-visual-paradigm($src, $exporter)) then 'visual-paradigm'
        else if (fp:is-modelio($src, $exporter)) then 'modelio'
        else if (fp:is-papyrus($src, $exporter)) then 'papyrus'
        else if (fp:is-eclipse-uml2(namespace-uri($src-model))) then 'eclipse-uml2'
        else 'unknown'"/>
  </xsl:function>

  <!-- the first id of $src that looks like an EA id (EAID_, EAPK_) or a
       StarUML one (AAAAAA...), if any -->
  <xsl:function name="fp:marked-id" as="xs:string?">
    <xsl:param name="src" as="document-node()"/>
    <xsl:sequence select="($src/*//@*:id[starts-with(., 'EAID_') or starts-with(., 'EAPK_') or starts-with(., 'AAAAAA')])[1]"/>
  </xsl:function>

  <!-- xmi:version as written, else from the XMI namespace -->
  <xsl:function name="fp:xmi-version" as="xs:string">
    <xsl:param name="src-root" as="element()"/>
    <xsl:param name="src-model" as="element()"/>
    <xsl:variable name="written" as="xs:string?"
        select="($src-root/@*[local-name() eq 'version'][fp:is-xmi-ns(namespace-uri())],
                 $src-model/@*[local-name() eq 'version'][fp:is-xmi-ns(namespace-uri())])[1]/string()"/>
    <xsl:variable name="ns" as="xs:string?"
        select="($src-root/namespace::*[fp:is-xmi-ns(.)], $src-root/@*[fp:is-xmi-ns(namespace-uri())]/namespace-uri())[1]"/>
    <xsl:variable name="step" as="xs:string" select="replace(string($ns), '^.*/', '')"/>
    <xsl:sequence select="
        if ($written) then $written
        else if ($step eq '20100901') then '2.4'
        else if ($step eq '20110701') then '2.4.1'
        else if ($step eq '20131001') then '2.5'
        else if ($step eq '20161101') then '2.5.1'
        else if ($step eq 'XMI') then '2.0'
        else $step"/>
  </xsl:function>
</xsl:stylesheet>
